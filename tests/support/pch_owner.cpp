// The translation unit that builds the tests' shared precompiled header (tests/CMakeLists.txt):
// the header is all it needs, so it has no code of its own.
