#include "export/pdf_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace billow {
namespace {

std::string pdfNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string rgb(const char* hex, const char* op) {
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(hex + 1, "%2x%2x%2x", &r, &g, &b);
  return pdfNumber(r / 255.0) + " " + pdfNumber(g / 255.0) + " " + pdfNumber(b / 255.0) + " " + op + "\n";
}
std::string rgb(Layer layer, const char* op) { return rgb(layerColor(layer), op); }

std::string text(double x, double y, double size, const std::string& s) {
  return "BT /F1 " + pdfNumber(size) + " Tf " + pdfNumber(x) + " " + pdfNumber(y) + " Td (" + escapePdfText(s) +
         ") Tj ET\n";
}

std::string moves(const Polygon2& points) {
  std::string s;
  for (size_t i = 0; i < points.size(); ++i)
    s += pdfNumber(points[i].x()) + " " + pdfNumber(points[i].y()) + (i ? " l\n" : " m\n");
  return s;
}

// A path stroked; a valve's gap also filled white over the seal band (B: fill and stroke).
std::string pathOps(const DrawnPath& p) {
  if (p.layer == Layer::Valve) return moves(p.points) + "h B\n";
  return moves(p.points) + (p.closed ? "h S\n" : "S\n");
}

// The drawing's paths and texts that touch `view`, in sheet millimetres (the caller sets the transform).
std::string drawingOps(const Drawing& d, const Box2& view, bool labels) {
  std::string s;
  // Seal bands first, tinted under every line (even-odd fill between the cut line and the sealing line).
  s += rgb(kSealTint, "rg");
  for (const DrawnPath& p : d.paths)
    if (p.layer == Layer::Seal && boundingBox(p.band).overlaps(view))
      s += moves(p.band) + "h\n" + moves(p.points) + "h f*\n";
  s += "1 1 1 rg\n";
  for (Layer layer : kLayers) {
    if (layer == Layer::Label) continue;
    s += rgb(layer, "RG");
    s += layer == Layer::Cut                            ? "0.25 w [] 0 d\n"
         : layer == Layer::Sew || layer == Layer::Valve ? "0.2 w [3 1.5] 0 d\n"
                                                        : "0.3 w [] 0 d\n";
    for (const DrawnPath& p : d.paths)
      if (p.layer == layer && boundingBox(p.points).overlaps(view)) s += pathOps(p);
  }
  if (!labels) return s;
  s += rgb(Layer::Label, "rg");
  for (const DrawnText& t : d.texts)
    if (pdfTextBox(t).overlaps(view))
      s += text(t.at.x() - pdfTextWidth(t.text, t.height) / 2, t.at.y(), t.height, t.text);
  return s;
}

std::string circle(const Vec2& c, double r) {
  const double k = 0.5523 * r;  // cubic Bezier quarter-circle handle
  auto p = [](double x, double y) { return pdfNumber(x) + " " + pdfNumber(y) + " "; };
  return p(c.x() + r, c.y()) + "m\n" + p(c.x() + r, c.y() + k) + p(c.x() + k, c.y() + r) + p(c.x(), c.y() + r) + "c\n" +
         p(c.x() - k, c.y() + r) + p(c.x() - r, c.y() + k) + p(c.x() - r, c.y()) + "c\n" + p(c.x() - r, c.y() - k) +
         p(c.x() - k, c.y() - r) + p(c.x(), c.y() - r) + "c\n" + p(c.x() + k, c.y() - r) + p(c.x() + r, c.y() - k) +
         p(c.x() + r, c.y()) + "c S\n";
}

// Footer of every page, in points: the 50 mm check square and the page's labels.
std::string footer(const PdfOptions& o, const std::string& label, int page, int pages) {
  const double m = o.margin * kPointsPerMm, side = kCheckSquareMm * kPointsPerMm;
  std::string s = "q 0 0 0 RG 0 0 0 rg 0.5 w [] 0 d\n% scale-check-square\n";
  s += pdfNumber(m) + " " + pdfNumber(m) + " " + pdfNumber(side) + " " + pdfNumber(side) + " re S\n";
  const bool inches = o.units == DisplayUnits::Inches;
  s += text(m + 4, m + side / 2, 8, "50 mm");
  s += text(m + 4, m + side / 2 - 10, 6, inches ? "= 1.97 in" : "check square");
  const double x = m + side + 12;
  s += text(x, m + side - 12, 12, label);
  s += text(x, m + side - 28, 9, o.title + "  -  page " + std::to_string(page) + " of " + std::to_string(pages));
  s += text(
      x, m + side - 42, 8,
      std::string("Print at 100 % (no fit to page); the square must measure 50 mm") + (inches ? " (1.97 in)." : "."));
  s += text(x, m + side - 54, 8, "cut: black   sew: blue dashed   notches: red   marks: align the crosshairs");
  return s + "Q\n";
}

}  // namespace

std::string escapePdfText(const std::string& utf8) {
  std::string out;
  for (size_t i = 0; i < utf8.size();) {
    unsigned char c = utf8[i++];
    unsigned cp = c;
    if (c >= 0x80) {  // two-byte UTF-8 covers Latin-1; anything else prints as '?'
      const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
      cp = extra == 1 && i < utf8.size() ? ((c & 0x1F) << 6) | (static_cast<unsigned char>(utf8[i]) & 0x3F) : '?';
      i = std::min(utf8.size(), i + extra);
      if (cp > 0xFF || cp < 0xA0) cp = '?';
    }
    if (cp == '(' || cp == ')' || cp == '\\') {
      out += '\\', out += char(cp);
    } else if (cp < 0x20 || cp >= 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\%03o", cp < 0x20 ? unsigned('?') : cp);
      out += buf;
    } else {
      out += char(cp);
    }
  }
  return out;
}

PdfTiling pdfTiling(const Drawing& d, const PdfOptions& o) { return pdfTiling(d, o.paper, o.overlap, o.margin); }

std::string writePdf(const Drawing& d, const PdfOptions& o) {
  const PdfTiling t = pdfTiling(d, o);
  const double k = kPointsPerMm, m = o.margin, overlap = t.overlap;
  const int pages = t.pageCount();
  std::vector<std::string> streams, labels;

  // Page 1: the overview, scaled to fit above the footer.
  {
    std::vector<std::string> summary = o.summary;
    if (t.skippedTiles() > 0)
      summary.push_back(std::to_string(t.skippedTiles()) + " of " + std::to_string(t.tiles()) +
                        " tiles have nothing to cut and are not printed; they are crossed out on the grid.");
    const double titleSpace = 14 + 5 * double(summary.size());
    const double availH = t.pageHeight - 2 * m - kPdfFooterMm - titleSpace;
    // Fit the tile grid (which reaches past the sheet), not just the sheet.
    const double gridW = (t.columns - 1) * t.stepX + t.contentWidth;
    const double scale = std::min(t.contentWidth / gridW, availH / t.height);
    const double ox = m + (t.contentWidth - scale * gridW) / 2, oy = m + kPdfFooterMm;
    std::string s = "q " + pdfNumber(k * scale) + " 0 0 " + pdfNumber(k * scale) + " " + pdfNumber(k * ox) + " " +
                    pdfNumber(k * oy) + " cm\n";
    Box2 all;
    all.add({-1e9, -1e9}), all.add({1e9, 1e9});
    s += "0.6 0.6 0.6 RG " + pdfNumber(0.5 / scale) + " w 0 0 " + pdfNumber(d.width) + " " + pdfNumber(d.length) +
         " re S\n";
    auto tileRect = [&](int r, int c) {
      const Box2 b = t.tileBox(r, c);
      return pdfNumber(b.lo.x()) + " " + pdfNumber(b.lo.y()) + " " + pdfNumber(t.contentWidth) + " " +
             pdfNumber(t.contentHeight) + " re";
    };
    s += "0.92 0.92 0.92 rg\n";  // skipped tiles shaded under the drawing, which may reach into their strips
    for (int r = 0; r < t.rows; ++r)
      for (int c = 0; c < t.columns; ++c)
        if (!t.isPrinted(r, c)) s += tileRect(r, c) + " f\n";
    s += drawingOps(d, all, true);
    // The tile grid with each tile's row and column, so a maker knows where each page goes; skipped tiles
    // are grey and crossed out, drawn first so that the printed tiles' edges stay green where they overlap.
    s += pdfNumber(0.3 / scale) + " w [] 0 d\n";
    for (bool printed : {false, true})
      for (int r = 0; r < t.rows; ++r)
        for (int c = 0; c < t.columns; ++c) {
          if (t.isPrinted(r, c) != printed) continue;
          const Box2 b = t.tileBox(r, c);
          s += printed ? "0.2 0.6 0.2 RG 0.2 0.6 0.2 rg\n" : "0.6 0.6 0.6 RG 0.6 0.6 0.6 rg\n";
          s += tileRect(r, c) + " S\n";
          if (!printed)
            s += pdfNumber(b.lo.x()) + " " + pdfNumber(b.lo.y()) + " m " + pdfNumber(b.hi.x()) + " " +
                 pdfNumber(b.hi.y()) + " l " + pdfNumber(b.lo.x()) + " " + pdfNumber(b.hi.y()) + " m " +
                 pdfNumber(b.hi.x()) + " " + pdfNumber(b.lo.y()) + " l S\n";
          const std::string lab = std::to_string(r + 1) + "," + std::to_string(c + 1);
          const double size = std::min(0.15 * t.contentWidth, 4 / scale);
          s += text(b.lo.x() + 0.5 * t.contentWidth - pdfTextWidth(lab, size) / 2, b.lo.y() + 0.5 * t.contentHeight,
                    size, lab);
        }
    s += "Q\nq 0 0 0 rg\n";
    double y = t.pageHeight - m - 6;
    s += text(k * m, k * y, 14, o.title + " - overview (not to scale)");
    for (const std::string& line : summary) y -= 5, s += text(k * m, k * y, 8, line);
    s += "Q\n";
    streams.push_back(s + footer(o, "overview", 1, pages));
    labels.push_back("overview");
  }
  // Tiles at true scale: sheet millimetres -> page points with the tile's origin at the content box.
  for (int r = 0; r < t.rows; ++r)
    for (int c = 0; c < t.columns; ++c) {
      if (!t.isPrinted(r, c)) continue;
      const Box2 view = t.tileBox(r, c);
      const double x0 = view.lo.x(), y0 = view.lo.y();
      std::string s = "q " + pdfNumber(k * m) + " " + pdfNumber(k * (m + kPdfFooterMm)) + " " +
                      pdfNumber(k * t.contentWidth) + " " + pdfNumber(k * t.contentHeight) + " re W n\n";
      s += pdfNumber(k) + " 0 0 " + pdfNumber(k) + " " + pdfNumber(k * (m - x0)) + " " +
           pdfNumber(k * (m + kPdfFooterMm - y0)) + " cm\n";
      s += drawingOps(d, view, true);
      // Alignment crosshairs in the middle of the overlap strips; each appears on every tile that shares it.
      s += "0 0 0 RG 0.2 w [] 0 d\n";
      for (int i = 0; i <= t.columns; ++i)
        for (int j = 0; j <= t.rows; ++j) {
          const Vec2 p(i * t.stepX + overlap / 2, t.height - j * t.stepY - overlap / 2);
          if (p.x() < x0 - 6 || p.x() > x0 + t.contentWidth + 6 || p.y() < y0 - 6 || p.y() > y0 + t.contentHeight + 6)
            continue;
          s += pdfNumber(p.x() - 6) + " " + pdfNumber(p.y()) + " m " + pdfNumber(p.x() + 6) + " " + pdfNumber(p.y()) +
               " l S\n";
          s += pdfNumber(p.x()) + " " + pdfNumber(p.y() - 6) + " m " + pdfNumber(p.x()) + " " + pdfNumber(p.y() + 6) +
               " l S\n";
          s += circle(p, 3);
        }
      s += "0.6 0.6 0.6 RG 0.2 w [1 1] 0 d " + pdfNumber(x0) + " " + pdfNumber(y0) + " " + pdfNumber(t.contentWidth) +
           " " + pdfNumber(t.contentHeight) + " re S\nQ\n";
      const std::string label = "row " + std::to_string(r + 1) + ", column " + std::to_string(c + 1);
      streams.push_back(s + footer(o, label, int(streams.size()) + 1, pages));
      labels.push_back(label);
    }

  // Objects: 1 catalog, 2 page tree, 3 font, 4 info, then page i = 5 + 2i and its contents 6 + 2i.
  std::string pdf = "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n";
  std::vector<size_t> offsets;
  auto object = [&](const std::string& body) {
    offsets.push_back(pdf.size());
    pdf += std::to_string(offsets.size()) + " 0 obj\n" + body + "\nendobj\n";
  };
  std::string nums;
  for (size_t i = 0; i < labels.size(); ++i)
    nums += std::to_string(i) + " << /P (" + escapePdfText(labels[i]) + ") >> ";
  object("<< /Type /Catalog /Pages 2 0 R /PageLabels << /Nums [" + nums + "] >> >>");
  std::string kids;
  for (int i = 0; i < pages; ++i) kids += std::to_string(5 + 2 * i) + " 0 R ";
  object("<< /Type /Pages /Kids [" + kids + "] /Count " + std::to_string(pages) + " >>");
  object("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>");
  object("<< /Title (" + escapePdfText(o.title) + ") /Producer (Billow) >>");
  const std::string box = "[0 0 " + pdfNumber(t.pageWidth * k) + " " + pdfNumber(t.pageHeight * k) + "]";
  for (int i = 0; i < pages; ++i) {
    object("<< /Type /Page /Parent 2 0 R /MediaBox " + box + " /Resources << /Font << /F1 3 0 R >> >> /Contents " +
           std::to_string(6 + 2 * i) + " 0 R >>");
    object("<< /Length " + std::to_string(streams[i].size()) + " >>\nstream\n" + streams[i] + "endstream");
  }
  const size_t xref = pdf.size();
  pdf += "xref\n0 " + std::to_string(offsets.size() + 1) + "\n0000000000 65535 f \n";
  for (size_t off : offsets) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%010zu 00000 n \n", off);
    pdf += buf;
  }
  pdf += "trailer\n<< /Size " + std::to_string(offsets.size() + 1) + " /Root 1 0 R /Info 4 0 R >>\nstartxref\n" +
         std::to_string(xref) + "\n%%EOF\n";
  return pdf;
}

}  // namespace billow
