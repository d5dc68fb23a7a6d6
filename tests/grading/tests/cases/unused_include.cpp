// case: an honest solution that includes doctest.h and uses nothing from it: allowed
// expect: * | pass
#include <doctest/doctest.h>
