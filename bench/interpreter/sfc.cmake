# bench_sfc: a 1,000-step SFC with parallel branches run by the VM, against plain C++ (issue 5).
add_executable(bench_sfc bench_sfc.cpp)
target_link_libraries(bench_sfc PRIVATE iec_interpreter)
