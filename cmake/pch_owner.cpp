// The library that owns the module libraries' shared precompiled header
// (cmake/ek_pch.cmake): Eigen and standard headers, parsed once.
