# freestand_test_paths: the one object holding the absolute paths the tests and benchmarks need
# (tests/support/paths.hpp). configure_file fills the source paths, file(GENERATE) the built
# executable's.
configure_file(${PROJECT_SOURCE_DIR}/cmake/test_paths.cpp.in
               ${PROJECT_BINARY_DIR}/generated/test_paths.cpp.in @ONLY)
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/generated/test_paths.cpp
     INPUT ${PROJECT_BINARY_DIR}/generated/test_paths.cpp.in)
add_library(freestand_test_paths STATIC ${PROJECT_BINARY_DIR}/generated/test_paths.cpp)
target_include_directories(freestand_test_paths PUBLIC ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(freestand_test_paths PRIVATE freestand_options)
