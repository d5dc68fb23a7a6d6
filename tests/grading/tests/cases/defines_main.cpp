// case: defines its own main (to print a fake report): refused at link time
// expect: * | build error | multiple definition of `main'
int main() { return 0; }
