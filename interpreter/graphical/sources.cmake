# LD and FBD/CFC lowering (graphicallowering.h).
target_sources(iec_interpreter PRIVATE
  graphical/graphicallowering.h
  graphical/graphicallowering.cpp
)
