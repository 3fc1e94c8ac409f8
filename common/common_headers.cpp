// Nothing of its own: the target common_headers compiles the precompiled header only
// (CMakeLists.txt).
