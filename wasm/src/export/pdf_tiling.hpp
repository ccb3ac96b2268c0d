// The printable PDF's tiles: the sheet cut into pages of A4 or US Letter that overlap by a strip, row 0 at
// the top, and which of them are printed. A tile with nothing drawn on it that no other printed tile shows
// is skipped; the others keep their row and column in the grid, so a maker still knows where each goes.
#pragma once
#include <string>
#include <vector>

#include "export/drawing.hpp"
#include "export/export_options.hpp"

namespace billow {

constexpr double kPdfFooterMm = 56;  // check square (50 mm) and page label below every tile

struct PdfTiling {
  double pageWidth = 0, pageHeight = 0;        // [mm]
  double contentWidth = 0, contentHeight = 0;  // [mm] sheet area shown per tile
  double stepX = 0, stepY = 0;                 // content minus overlap
  double overlap = 0;                          // [mm] strip shown on both neighbouring tiles
  int rows = 1, columns = 1;
  double height = 0;          // [mm] sheet height the rows cover (>= drawing length); row 0 is the top
  std::vector<char> printed;  // #rows * #columns, row by row from the top: the tile is a page

  bool isPrinted(int row, int column) const { return printed[row * columns + column] != 0; }
  int tiles() const { return rows * columns; }
  int printedTiles() const;
  int skippedTiles() const { return tiles() - printedTiles(); }
  int pageCount() const { return 1 + printedTiles(); }  // the overview, then the printed tiles
  Box2 tileBox(int row, int column) const;              // sheet area the tile shows [mm]
};

PdfTiling pdfTiling(const Drawing& drawing, PaperSize paper, double overlap, double margin);

// Where the PDF sets a label (rough Helvetica metrics, centred on its baseline point) [mm]; a tile that the
// box touches shows (part of) the label.
double pdfTextWidth(const std::string& text, double size);
Box2 pdfTextBox(const DrawnText& text);

}  // namespace billow
