# bench_ld: a 10,000-contact LD program run by the VM against the same logic in plain C++.
add_executable(bench_ld bench_ld.cpp)
target_link_libraries(bench_ld PRIVATE iec_interpreter)
