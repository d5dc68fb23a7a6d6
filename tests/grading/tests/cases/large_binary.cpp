// case: an honest solution with a 1.5 MB table in it: its test binary is larger than the output
// limit (1 MiB), which the sandbox must not apply to copying the binary in
// expect: * | pass
extern const unsigned char workbook_case_table[];
const unsigned char workbook_case_table[1536 * 1024] = {1};
