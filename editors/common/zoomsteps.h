#pragma once

namespace iec::editors {

// The fixed zoom levels every diagram view steps through (as in CODESYS: 25 % … 400 %).
// Pure functions so that the steps are tested as a table.
double nextZoomIn(double current);
double nextZoomOut(double current);
double clampZoom(double factor);
double minimumZoom();
double maximumZoom();

} // namespace iec::editors
