# The SFC engine (interpreter/sfc): semantics scan by scan, structure diagnostics, step options.
iec_add_test(tst_sfcengine SOURCES sfc/tst_sfcengine.cpp sfc/sfctesting.h LIBS iec_interpreter)
iec_add_test(tst_sfcchart SOURCES sfc/tst_sfcchart.cpp sfc/chartelements.h LIBS iec_interpreter)
