# SFC lowering (sfclowering.h; its working state in sfcloweringclass.h), the chart graph it works on (sfcgraph.h), the names of the
# implicit variables (sfcnames.h), the chart state the online mode shows (sfcstatus.h) and the
# textual SFC form <-> model (sfctext.h).
target_sources(iec_interpreter PRIVATE
  sfc/sfcgraph.h
  sfc/sfcgraph.cpp
  sfc/sfcnames.h
  sfc/sfclowering.h
  sfc/sfclowering.cpp
  sfc/sfcloweringclass.h
  sfc/sfcloweringphases.cpp
  sfc/sfcstatus.h
  sfc/sfcstatus.cpp
  sfc/sfctext.h
  sfc/sfctext.cpp
)
