#include "export/dxf_writer.hpp"

#include <cstdio>
#include <iterator>

namespace billow {
namespace {

struct Out {
  std::string s;
  void pair(int code, const std::string& value) { s += std::to_string(code) + "\n" + value + "\n"; }
  void pair(int code, int value) { pair(code, std::to_string(value)); }
  void real(int code, double value) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.6f", value);
    pair(code, buf);
  }
  void point(int base, const Vec2& p) { real(base, p.x()), real(base + 10, p.y()), real(base + 20, 0.0); }
};

// Decodes one UTF-8 code point at s[i] (advancing i); invalid bytes read as U+FFFD.
unsigned decodeUtf8(const std::string& s, size_t& i) {
  const unsigned char c = s[i++];
  if (c < 0x80) return c;
  const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : -1;
  if (extra < 0) return 0xFFFD;
  unsigned cp = c & (0x3F >> extra);
  for (int k = 0; k < extra; ++k) {
    if (i >= s.size() || (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) return 0xFFFD;
    cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3F);
  }
  return cp;
}

}  // namespace

const char* dxfLayerName(Layer layer) {
  switch (layer) {
    case Layer::Seal:
      return "SEAL_BAND";
    case Layer::Valve:
      return "VALVE";
    case Layer::Cut:
      return "CUT";
    case Layer::Sew:
      return "SEW";
    case Layer::Notch:
      return "NOTCH";
    case Layer::Label:
      return "LABEL";
  }
  return "0";
}

std::string escapeDxfText(const std::string& utf8) {
  std::string out;
  for (size_t i = 0; i < utf8.size();) {
    const unsigned cp = decodeUtf8(utf8, i);
    if (cp == '%') {
      out += "%%%";
    } else if (cp >= 0x20 && cp < 0x7F) {
      out += char(cp);
    } else if (cp >= 0x80) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "\\U+%04X", cp > 0xFFFF ? 0xFFFDu : cp);
      out += buf;
    }
  }
  return out;
}

std::string writeDxf(const Drawing& d) {
  Out o;
  o.pair(0, "SECTION"), o.pair(2, "HEADER");
  o.pair(9, "$ACADVER"), o.pair(1, "AC1009");
  o.pair(9, "$INSUNITS"), o.pair(70, 4);
  o.pair(9, "$MEASUREMENT"), o.pair(70, 1);  // metric
  o.pair(9, "$EXTMIN"), o.point(10, Vec2(0, 0));
  o.pair(9, "$EXTMAX"), o.point(10, Vec2(d.width, d.length));
  o.pair(0, "ENDSEC");

  o.pair(0, "SECTION"), o.pair(2, "TABLES");
  o.pair(0, "TABLE"), o.pair(2, "LTYPE"), o.pair(70, 1);
  o.pair(0, "LTYPE"), o.pair(2, "CONTINUOUS"), o.pair(70, 0), o.pair(3, "Solid line"), o.pair(72, 65);
  o.pair(73, 0), o.real(40, 0.0);
  o.pair(0, "ENDTAB");
  o.pair(0, "TABLE"), o.pair(2, "LAYER"), o.pair(70, int(std::size(kLayers)));
  for (Layer layer : kLayers) {
    o.pair(0, "LAYER"), o.pair(2, dxfLayerName(layer)), o.pair(70, 0);
    o.pair(62, layerAciColor(layer)), o.pair(6, "CONTINUOUS");
  }
  o.pair(0, "ENDTAB");
  o.pair(0, "ENDSEC");
  o.pair(0, "SECTION"), o.pair(2, "BLOCKS"), o.pair(0, "ENDSEC");

  o.pair(0, "SECTION"), o.pair(2, "ENTITIES");
  for (const DrawnPath& p : d.paths) {
    const char* layer = dxfLayerName(p.layer);
    if (p.points.size() == 2 && !p.closed) {
      o.pair(0, "LINE"), o.pair(8, layer), o.point(10, p.points[0]), o.point(11, p.points[1]);
      continue;
    }
    o.pair(0, "POLYLINE"), o.pair(8, layer), o.pair(66, 1), o.point(10, Vec2(0, 0)), o.pair(70, p.closed ? 1 : 0);
    for (const Vec2& v : p.points) o.pair(0, "VERTEX"), o.pair(8, layer), o.point(10, v);
    o.pair(0, "SEQEND"), o.pair(8, layer);
  }
  for (const DrawnText& t : d.texts) {
    // Centred text: 72 = 1 (centre); the alignment point (11/21) is the one that counts.
    o.pair(0, "TEXT"), o.pair(8, dxfLayerName(t.layer)), o.point(10, t.at),
        o.real(40, 0.7 * t.height);  // DXF gives the cap height, about 0.7 em
    o.pair(1, escapeDxfText(t.text)), o.pair(72, 1), o.point(11, t.at);
  }
  o.pair(0, "ENDSEC");
  o.pair(0, "EOF");
  return o.s;
}

}  // namespace billow
