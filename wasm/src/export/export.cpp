#include "export/export.hpp"

#include "export/dxf_writer.hpp"
#include "export/layout.hpp"
#include "export/pdf_writer.hpp"
#include "export/statistics.hpp"
#include "export/svg_writer.hpp"

namespace billow {

ExportBundle exportPattern(const Pattern& pattern, const ExportOptions& options) {
  const SheetLayout layout = layoutSheet(pattern, options);
  const nlohmann::json stats = exportStatistics(pattern, layout, options);
  PdfOptions pdf;
  pdf.paper = options.paper;
  pdf.overlap = options.tileOverlap;
  pdf.units = options.units;
  pdf.title = options.title;
  pdf.summary = summaryLines(stats, options);
  ExportBundle out;
  out.svg = writeSvg(layout.drawing, options.title);
  out.dxf = writeDxf(layout.drawing);
  out.pdf = writePdf(layout.drawing, pdf);
  out.statistics = stats.dump(2);
  for (const PanelLayout& panel : layout.panels) {
    out.cutLines.push_back(panel.cut);
    out.placements.push_back(panel.placement);
  }
  out.outlines = layout.outlines;
  out.sheetWidth = layout.drawing.width;
  out.sheetLength = layout.drawing.length;
  out.utilisation = layout.nest.utilisation;
  out.notchTicks = notchTicks(layout, options);
  out.valveMarks.resize(layout.panels.size());
  for (const ValveGap& gap : layout.valveGaps) out.valveMarks[gap.panel].push_back(gap.mark);
  return out;
}

}  // namespace billow
