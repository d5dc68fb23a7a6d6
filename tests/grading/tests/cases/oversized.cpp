// case: a file larger than the size limit (the reference, padded with a comment)
// make: oversized
// expect: * | missing | more than the limit
