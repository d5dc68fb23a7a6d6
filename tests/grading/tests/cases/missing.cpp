// case: an empty submission folder
// make: missing
// expect: * | missing | is not in the submission
