// Options of the fabrication outputs (cut files, printable tiles, statistics). Lengths in millimetres,
// because that is how makers set up plotters, laser cutters and printers.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace billow {

enum class PaperSize { A4, Letter };
enum class DisplayUnits { Millimeters, Inches };  // units of the numbers printed for people (files stay in mm)

// A fill valve: a gap left in a seam (unsealed, unsewn) where the valve or a straw goes in, at the same place
// on both pieces. `at` is its centre as a share of the seam's length from the seam's start (both sides run
// the same way, export/outline.hpp SeamSide).
struct FillValve {
  int seam = 0;       // seam id (S<id + 1>)
  double at = 0.5;    // [0, 1]
  double width = 20;  // [mm] along the seam
};

struct ExportOptions {
  double allowance = 10;  // [mm] seam allowance on every seam; sealed: the seal band
  bool sealed = false;    // heat sealed (foil): the allowance is a seal band, drawn as a band
  std::vector<FillValve> valves;
  double freeEdgeAllowance = -1;                      // [mm] on unsewn edges (openings, hems); < 0: same as `allowance`
  std::vector<std::pair<int, double>> seamAllowance;  // per-seam overrides: (seam id, width [mm])
  double notchSpacing = 100;        // [mm] between registration notches along a seam; 0 = junctions only
  double notchLength = 3;           // [mm] each side of the cut line (at most half the allowance inside)
  double sheetWidth = 1000;         // [mm] width of the sheet or roll the pieces are nested on
  double gap = 5;                   // [mm] between nested pieces and from the sheet edges
  bool allowRotation = true;        // nest pieces at 0/90/180/270 degrees and along their principal axis
  bool grainLock = false;           // keep each panel's y axis along the roll (0 or 180 degrees only)
  PaperSize paper = PaperSize::A4;  // tiles of the printable PDF
  double tileOverlap = 10;          // [mm] printed twice on neighbouring tiles, for gluing them together
  DisplayUnits units = DisplayUnits::Millimeters;
  // Sewing time estimate: a home machine sews foil or ripstop at about 0.5 m of seam per minute once the
  // pieces are pinned at the notches; matching, pinning and turning add about 2 minutes per seam.
  double sewingMetersPerMinute = 0.5;
  double minutesPerSeam = 2;
  std::string title = "Billow pattern";
};

}  // namespace billow
