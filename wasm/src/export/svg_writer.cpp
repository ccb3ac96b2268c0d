#include "export/svg_writer.hpp"

#include <algorithm>
#include <cstdio>

namespace billow {
namespace {

std::string svgNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);  // 0.1 um: lengths round-trip far below 0.01 mm
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

}  // namespace

std::string escapeXml(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        if (c >= 0x20 || c == '\t') out += char(c);  // XML 1.0 forbids most control characters
    }
  }
  return out;
}

std::string writeSvg(const Drawing& d, const std::string& title) {
  const double W = d.width, L = d.length;
  auto X = [](double x) { return svgNumber(x); };
  auto Y = [L](double y) { return svgNumber(L - y); };
  std::string s;
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" ";
  s += "width=\"" + svgNumber(W) + "mm\" height=\"" + svgNumber(L) + "mm\" viewBox=\"0 0 " + svgNumber(W) + " " +
       svgNumber(L) + "\">\n";
  s += "<title>" + escapeXml(title) + "</title>\n";
  // A path's d attribute: "M x y x y ..." and " Z" when closed.
  const auto pathData = [&](const Polygon2& points, bool closed) {
    std::string out = "M";
    for (size_t i = 0; i < points.size(); ++i) out += (i ? " " : "") + X(points[i].x()) + " " + Y(points[i].y());
    return closed ? out + " Z" : out;
  };
  for (Layer layer : kLayers) {
    const bool used = std::any_of(d.paths.begin(), d.paths.end(), [&](const DrawnPath& p) { return p.layer == layer; });
    // Seal band or sewing line, whichever the joining draws; valves only when placed.
    if (!used && (layer == Layer::Seal || layer == Layer::Sew || layer == Layer::Valve)) continue;
    const std::string name = layerName(layer), color = layerColor(layer);
    s += "<g id=\"" + name + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + name + "\"";
    if (layer == Layer::Label) {
      s += " fill=\"" + color + "\" font-family=\"Helvetica, Arial, sans-serif\" text-anchor=\"middle\">\n";
      for (const DrawnText& t : d.texts)
        if (t.layer == layer)
          s += "<text x=\"" + X(t.at.x()) + "\" y=\"" + Y(t.at.y()) + "\" font-size=\"" + svgNumber(t.height) +
               "\" data-panel=\"" + std::to_string(t.panel) + "\">" + escapeXml(t.text) + "</text>\n";
    } else if (layer == Layer::Seal) {
      // The band tinted between the cut line and the sealing line (even-odd fill), then the sealing line.
      s += " stroke=\"" + color + "\" stroke-width=\"0.2\">\n";
      for (const DrawnPath& p : d.paths)
        if (p.layer == layer && !p.points.empty())
          s += "<path data-panel=\"" + std::to_string(p.panel) + "\" fill=\"" + kSealTint +
               "\" fill-rule=\"evenodd\" stroke=\"none\" d=\"" + pathData(p.band, true) + " " +
               pathData(p.points, true) + "\"/>\n<path data-panel=\"" + std::to_string(p.panel) +
               "\" fill=\"none\" d=\"" + pathData(p.points, true) + "\"/>\n";
    } else {
      // Hairlines for cutters (0.1 mm); the sewing line dashed as on paper patterns; a valve's gap filled white
      // over the seal band, so the band shows where not to seal.
      s += std::string(" fill=\"") + (layer == Layer::Valve ? "#ffffff" : "none") + "\" stroke=\"" + color +
           "\" stroke-width=\"" + (layer == Layer::Cut ? "0.1" : "0.2") + "\"";
      if (layer == Layer::Sew || layer == Layer::Valve) s += " stroke-dasharray=\"3 1.5\"";
      s += ">\n";
      for (const DrawnPath& p : d.paths) {
        if (p.layer != layer || p.points.empty()) continue;
        s += "<path data-panel=\"" + std::to_string(p.panel) + "\" d=\"" + pathData(p.points, p.closed) + "\"/>\n";
      }
    }
    s += "</g>\n";
  }
  s += "</svg>\n";
  return s;
}

}  // namespace billow
