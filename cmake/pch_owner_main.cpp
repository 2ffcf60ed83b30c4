// The program that owns the programs' shared precompiled header
// (cmake/ek_pch.cmake): Eigen and standard headers, parsed once.
int main() { return 0; }
