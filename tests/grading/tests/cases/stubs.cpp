// case: the untouched stubs: every exercise not started, none crashed
// make: stubs
// expect: * | not started | todo(
