#include "export/pdf_tiling.hpp"

#include <algorithm>
#include <cmath>

namespace billow {
namespace {

// One axis of the grid: tile k starts at k * step and shows step + overlap. Cell 2k is the part only tile k
// shows, cell 2k - 1 the strip tiles k - 1 and k share; u runs from the grid's start (left, or top for rows).
struct Axis {
  double step = 1, overlap = 0;
  int tiles = 1;

  int cells() const { return 2 * tiles - 1; }
  int cell(double u) const {
    u = std::clamp(u, -1.0, tiles * step + overlap + 1);
    const int k = int(std::floor(u / step));
    return std::clamp(k >= 1 && u - k * step < overlap ? 2 * k - 1 : 2 * k, 0, cells() - 1);
  }
  // Where one cell ends and the next begins.
  std::vector<double> edges() const {
    std::vector<double> out;
    for (int k = 1; k < tiles; ++k) out.push_back(k * step), out.push_back(k * step + overlap);
    return out;
  }
};

// The cells of the grid that something drawn on the sheet touches, row by row from the top.
class TouchedCells {
 public:
  TouchedCells(const PdfTiling& t)
      : across_{t.stepX, t.overlap, t.columns},
        along_{t.stepY, t.overlap, t.rows},
        height_(t.height),
        acrossEdges_(across_.edges()),
        alongEdges_(along_.edges()),
        touched_(size_t(across_.cells()) * along_.cells(), 0) {}

  int rows() const { return along_.cells(); }
  int columns() const { return across_.cells(); }
  bool touched(int fy, int fx) const { return touched_[fy * columns() + fx] != 0; }

  void addPath(const DrawnPath& path) {
    const Polygon2& p = path.points;
    if (p.size() == 1) mark(p[0]);
    for (size_t i = 0; i + 1 < p.size(); ++i) addSegment(p[i], p[i + 1]);
    if (path.closed && p.size() > 2) addSegment(p.back(), p.front());
  }
  void addBox(const Box2& b) {
    if (b.empty()) return;
    for (int fy = along_.cell(height_ - b.hi.y()); fy <= along_.cell(height_ - b.lo.y()); ++fy)
      for (int fx = across_.cell(b.lo.x()); fx <= across_.cell(b.hi.x()); ++fx) touched_[fy * columns() + fx] = 1;
  }

 private:
  void mark(const Vec2& p) { touched_[along_.cell(height_ - p.y()) * columns() + across_.cell(p.x())] = 1; }
  // Split the segment where it crosses from one cell to the next; each piece lies in the cell of its middle.
  void addSegment(const Vec2& a, const Vec2& b) {
    if ((b - a).norm() == 0) {
      mark(a);
      return;
    }
    std::vector<double> ts = {0, 1};
    auto crossings = [&](double ua, double ub, const std::vector<double>& edges) {
      for (double e : edges)
        if ((ua - e) * (ub - e) < 0) ts.push_back((e - ua) / (ub - ua));
    };
    crossings(a.x(), b.x(), acrossEdges_);
    crossings(height_ - a.y(), height_ - b.y(), alongEdges_);
    std::sort(ts.begin(), ts.end());
    for (size_t i = 0; i + 1 < ts.size(); ++i)
      if (ts[i + 1] > ts[i]) mark(a + 0.5 * (ts[i] + ts[i + 1]) * (b - a));
  }

  Axis across_, along_;
  double height_;
  std::vector<double> acrossEdges_, alongEdges_;
  std::vector<char> touched_;
};

// Tiles (index row * columns + column) that show cell (fy, fx).
std::vector<int> tilesShowing(int fy, int fx, int columns) {
  std::vector<int> out;
  for (int r = fy / 2; r <= (fy + 1) / 2; ++r)
    for (int c = fx / 2; c <= (fx + 1) / 2; ++c) out.push_back(r * columns + c);
  return out;
}

// A tile is printed when something drawn lies on it and on no other printed tile (first the tiles whose own
// part is touched, then one tile for each touched overlap strip no printed tile shows), and when two printed
// tiles meet only at a corner the drawing crosses, the tile beside both is printed too: every piece of every
// outline is then on some page, and pages holding one piece join along an edge with two crosshairs to align.
std::vector<char> tilesToPrint(const Drawing& d, const PdfTiling& t) {
  TouchedCells cells(t);
  for (const DrawnPath& p : d.paths) cells.addPath(p);
  for (const DrawnText& text : d.texts) cells.addBox(pdfTextBox(text));

  std::vector<char> printed(t.tiles(), 0);
  std::vector<int> content(t.tiles(), 0);  // touched cells each tile shows
  auto shown = [&](const std::vector<int>& tiles) {
    return std::any_of(tiles.begin(), tiles.end(), [&](int tile) { return printed[tile] != 0; });
  };
  for (int fy = 0; fy < cells.rows(); ++fy)
    for (int fx = 0; fx < cells.columns(); ++fx) {
      if (!cells.touched(fy, fx)) continue;
      const std::vector<int> tiles = tilesShowing(fy, fx, t.columns);
      for (int tile : tiles) ++content[tile];
      if (tiles.size() == 1) printed[tiles[0]] = 1;
    }
  // Touched strips no printed tile shows: the tile that shows most of them, until none is left.
  for (;;) {
    std::vector<int> gain(t.tiles(), 0);
    for (int fy = 0; fy < cells.rows(); ++fy)
      for (int fx = 0; fx < cells.columns(); ++fx) {
        const std::vector<int> tiles = tilesShowing(fy, fx, t.columns);
        if (cells.touched(fy, fx) && !shown(tiles))
          for (int tile : tiles) ++gain[tile];
      }
    const auto best = std::max_element(gain.begin(), gain.end());
    if (*best == 0) break;
    printed[best - gain.begin()] = 1;
  }
  // Touched corners where only two diagonal tiles are printed: one of the other two, the fuller one.
  for (bool added = true; added;) {
    added = false;
    for (int fy = 1; fy < cells.rows(); fy += 2)
      for (int fx = 1; fx < cells.columns(); fx += 2) {
        if (!cells.touched(fy, fx)) continue;
        const int tl = (fy / 2) * t.columns + fx / 2, tr = tl + 1, bl = tl + t.columns, br = bl + 1;
        const bool falling = printed[tl] && printed[br] && !printed[tr] && !printed[bl];
        const bool rising = printed[tr] && printed[bl] && !printed[tl] && !printed[br];
        if (!falling && !rising) continue;
        const int first = falling ? tr : tl, second = falling ? bl : br;
        printed[content[second] > content[first] ? second : first] = 1;
        added = true;
      }
  }
  return printed;
}

}  // namespace

int PdfTiling::printedTiles() const { return int(std::count(printed.begin(), printed.end(), 1)); }

Box2 PdfTiling::tileBox(int row, int column) const {
  const double x0 = column * stepX, y0 = height - row * stepY - contentHeight;
  Box2 b;
  b.add({x0, y0}), b.add({x0 + contentWidth, y0 + contentHeight});
  return b;
}

double pdfTextWidth(const std::string& s, double size) {
  double w = 0;
  for (unsigned char c : s)
    w += (c == ' ' || c == 'i' || c == 'l' || c == '.' || c == ',') ? 0.28 : (c >= 'A' && c <= 'Z') ? 0.67 : 0.55;
  return w * size;
}

Box2 pdfTextBox(const DrawnText& t) {
  const double w = pdfTextWidth(t.text, t.height);
  Box2 b;
  b.add(t.at - Vec2(w / 2, 0)), b.add(t.at + Vec2(w / 2, t.height));
  return b;
}

PdfTiling pdfTiling(const Drawing& d, PaperSize paper, double overlap, double margin) {
  PdfTiling t;
  t.pageWidth = paper == PaperSize::A4 ? 210.0 : 215.9;
  t.pageHeight = paper == PaperSize::A4 ? 297.0 : 279.4;
  t.contentWidth = t.pageWidth - 2 * margin;
  t.contentHeight = t.pageHeight - 2 * margin - kPdfFooterMm;
  t.overlap = std::clamp(overlap, 0.0, 0.5 * std::min(t.contentWidth, t.contentHeight));
  t.stepX = t.contentWidth - t.overlap;
  t.stepY = t.contentHeight - t.overlap;
  t.columns = std::max(1, int(std::ceil((d.width - t.overlap) / t.stepX - 1e-9)));
  t.rows = std::max(1, int(std::ceil((d.length - t.overlap) / t.stepY - 1e-9)));
  t.height = (t.rows - 1) * t.stepY + t.contentHeight;
  t.printed = tilesToPrint(d, t);
  return t;
}

}  // namespace billow
