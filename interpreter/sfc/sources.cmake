# SFC lowering (sfclowering.h) and the chart state the online mode shows (sfcstatus.h).
target_sources(iec_interpreter PRIVATE
  sfc/sfclowering.h
  sfc/sfclowering.cpp
  sfc/sfcstatus.h
  sfc/sfcstatus.cpp
)
