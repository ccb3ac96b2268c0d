// Minimal readers for what the export writers produce (tests only): SVG paths per layer group, DXF
// POLYLINEs/LINEs/TEXTs per layer, and a few PDF facts. They read back our own output, nothing more.
#pragma once
#include <cctype>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "export/polygon.hpp"

namespace billow::test {

struct ReadPath {
  std::string layer;
  bool closed = false;
  Polygon2 points;  // in the sheet frame (y up), mm
};

// <g id="LAYER" ...> ... <path d="M x y x y ... Z"/> ... </g>; SVG y is flipped back with the viewBox height.
// Plain string search (std::regex recurses per character and overflows on large files).
inline std::vector<ReadPath> readSvgPaths(const std::string& svg) {
  std::vector<ReadPath> out;
  const size_t vb = svg.find("viewBox=\"0 0 ");
  double width = 0, height = 0;
  if (vb != std::string::npos) std::istringstream(svg.substr(vb + 13, 64)) >> width >> height;
  for (size_t g = svg.find("<g id=\""); g != std::string::npos; g = svg.find("<g id=\"", g + 1)) {
    const size_t nameEnd = svg.find('"', g + 7), groupEnd = svg.find("</g>", g);
    const std::string layer = svg.substr(g + 7, nameEnd - g - 7);
    for (size_t p = svg.find("<path", g); p != std::string::npos && p < groupEnd; p = svg.find("<path", p + 1)) {
      const size_t d = svg.find(" d=\"M", p) + 5, dEnd = svg.find('"', d);
      std::string body = svg.substr(d, dEnd - d);
      ReadPath rp;
      rp.layer = layer;
      if (!body.empty() && body.back() == 'Z') rp.closed = true, body.pop_back();
      std::istringstream in(body);
      double x, y;
      while (in >> x >> y) rp.points.push_back({x, height - y});
      out.push_back(rp);
    }
  }
  return out;
}

struct DxfFile {
  std::vector<std::pair<int, std::string>> pairs;          // every group code / value
  std::vector<ReadPath> paths;                             // POLYLINE (closed flag 70 & 1) and LINE
  std::vector<std::pair<std::string, std::string>> texts;  // (layer, value)
  std::map<std::string, int> layerColors;                  // from the LAYER table
};

inline DxfFile readDxf(const std::string& text) {
  DxfFile f;
  std::istringstream in(text);
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) f.pairs.push_back({std::atoi(code.c_str()), value});
  const auto& P = f.pairs;
  for (size_t i = 0; i < P.size(); ++i) {
    if (P[i].first != 0) continue;
    // Collect this entity's group codes up to the next 0 group.
    std::multimap<int, std::string> g;
    size_t j = i + 1;
    for (; j < P.size() && P[j].first != 0; ++j) g.insert(P[j]);
    auto get = [&](int c) {
      auto it = g.find(c);
      return it == g.end() ? std::string() : it->second;
    };
    if (P[i].second == "LAYER" && !get(2).empty() && !get(62).empty()) f.layerColors[get(2)] = std::stoi(get(62));
    if (P[i].second == "LINE")
      f.paths.push_back(
          {get(8), false, {{std::stod(get(10)), std::stod(get(20))}, {std::stod(get(11)), std::stod(get(21))}}});
    if (P[i].second == "TEXT") f.texts.push_back({get(8), get(1)});
    if (P[i].second == "POLYLINE") {
      ReadPath rp;
      rp.layer = get(8);
      rp.closed = (std::atoi(get(70).c_str()) & 1) != 0;
      // VERTEX entities follow until SEQEND.
      for (size_t k = j; k < P.size() && !(P[k].first == 0 && P[k].second == "SEQEND"); ++k)
        if (P[k].first == 10) rp.points.push_back({std::stod(P[k].second), std::stod(P[k + 1].second)});
      f.paths.push_back(rp);
    }
  }
  return f;
}

inline double pathLength(const ReadPath& p) {
  double l = 0;
  for (size_t i = 0; i + 1 < p.points.size(); ++i) l += (p.points[i + 1] - p.points[i]).norm();
  if (p.closed && p.points.size() > 1) l += (p.points.front() - p.points.back()).norm();
  return l;
}

inline int countPdfPages(const std::string& pdf) {
  int n = 0;
  for (size_t at = pdf.find("/Type /Page"); at != std::string::npos; at = pdf.find("/Type /Page", at + 1))
    if (at + 11 >= pdf.size() || !std::isalpha(static_cast<unsigned char>(pdf[at + 11]))) ++n;  // not /Pages
  return n;
}

}  // namespace billow::test
