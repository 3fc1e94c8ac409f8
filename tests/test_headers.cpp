// Nothing of its own: the target test_headers compiles the tests' precompiled header only
// (CMakeLists.txt).
