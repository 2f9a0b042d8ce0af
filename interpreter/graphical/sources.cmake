# LD and FBD/CFC lowering (graphicallowering.h).
target_sources(iec_interpreter PRIVATE
  graphical/graphicallowering.h
  graphical/graphicallowering.cpp
  graphical/astbuild.h
  graphical/astbuild.cpp
  graphical/network.h
  graphical/network.cpp
  graphical/evaluator.h
  graphical/evaluator.cpp
  graphical/typeguess.h
  graphical/typeguess.cpp
)
