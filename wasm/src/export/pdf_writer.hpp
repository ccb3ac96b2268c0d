// Printable PDF 1.4 (written by hand, no library): page 1 is an overview of the whole sheet scaled to fit,
// with the tile grid; then the sheet at true scale in tiles of A4 or US Letter, row by row from the top,
// leaving out the tiles with nothing to cut (pdf_tiling.hpp), which the overview crosses out and counts.
// Neighbouring tiles share `overlap` mm; crosshair alignment marks sit in the middle of each overlap strip at
// the tile corners. Every page carries a 50 mm check square (drawn in points, outside any scaling) with its
// label, and its page label ("row 2, column 3"), also set as the PDF's /PageLabels.
#pragma once
#include <string>
#include <vector>

#include "export/drawing.hpp"
#include "export/export_options.hpp"
#include "export/pdf_tiling.hpp"

namespace billow {

struct PdfOptions {
  PaperSize paper = PaperSize::A4;
  double overlap = 10;  // [mm]
  double margin = 10;   // [mm] unprintable border of home printers
  DisplayUnits units = DisplayUnits::Millimeters;
  std::string title = "Billow pattern";
  std::vector<std::string> summary;  // lines printed on the overview
};

// The tiles of `drawing` for these options (pdf_tiling.hpp).
PdfTiling pdfTiling(const Drawing& drawing, const PdfOptions& options);

constexpr double kPointsPerMm = 72.0 / 25.4;
constexpr double kCheckSquareMm = 50.0;

std::string writePdf(const Drawing& drawing, const PdfOptions& options);

// A PDF string literal body: UTF-8 to WinAnsi (Latin-1 subset, else '?'), with \ ( ) and non-printing bytes
// escaped.
std::string escapePdfText(const std::string& utf8);

}  // namespace billow
