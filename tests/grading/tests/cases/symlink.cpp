// case: exercises/rotation.cpp is a symbolic link (to the reference solution)
// make: symlink
// expect: * | missing | symbolic link
