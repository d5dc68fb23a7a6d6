// case: one line, an #include of the reference solution through the API's include path (-I<workbook>/exercises): the compile sees only the API, so it is a build error that names only the submission's own file
// base: none
// expect: * | build error | exercises/rotation.cpp:1
#include "../solutions/rotation.cpp"
