// The program that owns the tests' precompiled header (tests/CMakeLists.txt):
// GoogleTest and Eigen, parsed once and reused by every test program.
int main() { return 0; }
