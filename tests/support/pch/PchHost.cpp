// The host of a precompiled header (tests/CMakeLists.txt): compiling it builds the header that
// the test programs reuse. The program itself does nothing.
int main() { return 0; }
