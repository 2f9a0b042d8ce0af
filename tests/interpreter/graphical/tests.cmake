# Tests of the LD/FBD lowering (interpreter/graphical).
iec_add_test(tst_ldlowering SOURCES graphical/tst_ldlowering.cpp graphical/diagram.h LIBS iec_interpreter)
iec_add_test(tst_fbdlowering SOURCES graphical/tst_fbdlowering.cpp graphical/diagram.h LIBS iec_interpreter)
iec_add_test(tst_graphicallanguages SOURCES graphical/tst_graphicallanguages.cpp graphical/diagram.h LIBS iec_interpreter)
iec_add_test(tst_graphicalcorpus SOURCES graphical/tst_graphicalcorpus.cpp LIBS iec_interpreter)
iec_add_test(tst_graphicalseams SOURCES graphical/tst_graphicalseams.cpp graphical/diagram.h LIBS iec_interpreter)
