// case: the reference solutions themselves, for every topic of the workbook
// make: reference
// expect: * | pass
