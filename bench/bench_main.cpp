// Native benchmark of the inflation simulator (bench/README.md): per example and size, Newton iterations,
// time to equilibrium (relative residual 1e-5), one sparse factorization of the final Hessian (the floor
// per iteration), peak RSS, and for the Mylar balloon the ratios against Paulsen's numbers.
//   billow_bench [--json] [--sizes 700,3000,15000,60000] [--examples mylar,sphere3,pillow:20] [--radius 0.3]
//                [--max-seconds S]   (a solve stops after S seconds and is reported as not converged)
//                [--stiffening K]    (Young's modulus x K: the Mylar balloon tends to Paulsen's inextensible
//                                     shape as K grows, DESIGN.md)
// An example named NAME:R is the example NAME with aspect R (pillow:20 is a 20:1 tube).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "simulate/coarse_start.hpp"
#include "simulate/example_patterns.hpp"
#include "simulate/inflate.hpp"

namespace {

using namespace billow;
using Clock = std::chrono::steady_clock;

double peakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // Linux: kilobytes
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  bool asJson = false;
  std::vector<std::string> sizes = {"700", "3000", "15000", "60000"}, examples = {"mylar", "sphere3"};
  double radius = 0.3, maxSeconds = 120, stiffening = 1;
  InflateOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--json")
      asJson = true;
    else if (a == "--sizes" && hasValue)
      sizes = split(argv[++i]);
    else if (a == "--examples" && hasValue)
      examples = split(argv[++i]);
    else if (a == "--radius" && hasValue)
      radius = std::stod(argv[++i]);
    else if (a == "--max-seconds" && hasValue)
      maxSeconds = std::stod(argv[++i]);
    else if (a == "--stiffening" && hasValue)
      stiffening = std::stod(argv[++i]);
    else if (a == "--spherical-start")
      options.coarseStartTriangles = 0;
    else {
      std::fprintf(stderr,
                   "usage: billow_bench [--json] [--sizes N,N,..] [--examples mylar,sphere3,pillow:20] [--radius M] "
                   "[--max-seconds S] [--stiffening K] [--spherical-start]\n");
      return 2;
    }
  }
  nlohmann::json rows = nlohmann::json::array();
  if (!asJson)
    std::printf("%-16s %7s %6s %5s %6s %9s %9s %9s %8s %8s %9s %9s %5s\n", "example", "tris", "verts", "iters", "facts",
                "start s", "solve s", "factor ms", "setup ms", "RSS MB", "rim/a", "thick/rim", "conv");
  for (const std::string& example : examples)
    for (const std::string& size : sizes) {
      const size_t colon = example.find(':');
      const std::string name = example.substr(0, colon);
      ExampleOptions eo;
      if (colon != std::string::npos) eo.aspect = std::stod(example.substr(colon + 1));
      eo.triangles = std::stoi(size);
      eo.size = radius;
      eo.material.youngsModulus *= stiffening;
      const Pattern p = examplePattern(name, eo);
      // Timed from the pattern: sewing, the start (the coarse-to-fine start inflates coarser patterns
      // first, coarse_start.hpp) and Newton to the tolerance.
      const auto t0 = Clock::now();
      SewnMesh mesh = sewPattern(p);
      StartReport start;
      const Vertices x0 = startPositions(p, mesh, options, &start);
      InflationSolver solver(std::move(mesh), p.material, p.pressure, options, x0);
      while (solver.step(1) == InflateState::Running)
        if (std::chrono::duration<double>(Clock::now() - t0).count() > maxSeconds) break;
      const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      double factorMs = 1e300;
      for (int k = 0; k < 3; ++k) factorMs = std::min(factorMs, solver.timeFactorization());
      nlohmann::json row = {{"example", example},
                            {"triangles", solver.mesh().numTriangles()},
                            {"stiffening", stiffening},
                            {"vertices", solver.mesh().numVertices},
                            {"iterations", solver.iterations()},
                            {"coarseLevels", start.levels},
                            {"coarseTriangles", start.coarseTriangles},
                            {"coarseIterations", start.coarseIterations},
                            {"startMs", start.coarseMs},
                            {"factorizations", solver.timings().factorizations},
                            {"raisedPivots", solver.timings().raisedPivots},
                            {"seconds", seconds},
                            {"factorMs", factorMs},
                            {"setupMs", solver.timings().setupMs},
                            {"assembleMs", solver.timings().assembleMs},
                            {"lineSearchMs", solver.timings().lineSearchMs},
                            {"peakRssMb", peakRssMb()},
                            {"factorNonZeros", solver.timings().factorNonZeros},
                            {"factorMflops", solver.timings().factorFlops * 1e-6},
                            {"residual", solver.residual()},
                            {"converged", solver.state() == InflateState::Converged}};
      double rim = 0, thick = 0;
      if (name == "mylar") {
        const MylarShape s = measureMylar(solver.mesh(), solver.positions());
        rim = s.rimRadius / radius;
        thick = s.thickness / s.rimRadius;
        row["rimOverDisc"] = rim;
        row["thicknessOverRim"] = thick;
        row["poleThicknessOverRim"] = s.poleThickness / s.rimRadius;
        row["rimError"] = rim / kMylarRimOverDisc - 1;
        row["thicknessError"] = thick / kMylarThicknessOverRim - 1;
      }
      rows.push_back(row);
      if (!asJson) {
        std::printf("%-16s %7d %6d %5d %6d %9.3f %9.3f %9.2f %8.1f %8.1f ", example.c_str(),
                    solver.mesh().numTriangles(), solver.mesh().numVertices, solver.iterations(),
                    solver.timings().factorizations, start.coarseMs * 1e-3, seconds, factorMs, solver.timings().setupMs,
                    peakRssMb());
        if (name == "mylar")
          std::printf("%9.5f %9.5f", rim, thick);
        else
          std::printf("%9s %9s", "-", "-");
        std::printf(" %5s\n", solver.state() == InflateState::Converged ? "yes" : "NO");
        std::fflush(stdout);
      }
    }
  if (asJson)
    std::printf("%s\n",
                nlohmann::json(
                    {{"runtime", "native"},
                     {"reference", {{"rimOverDisc", kMylarRimOverDisc}, {"thicknessOverRim", kMylarThicknessOverRim}}},
                     {"rows", rows}})
                    .dump(2)
                    .c_str());
  else
    std::printf("Paulsen: rim/a = %.5f, thickness/rim = %.5f\n", kMylarRimOverDisc, kMylarThicknessOverRim);
  return 0;
}
