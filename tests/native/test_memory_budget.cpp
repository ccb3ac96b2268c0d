// The memory a computation needs, predicted before it starts (util/memory_budget.hpp): the models grow
// as they should, a need over the budget is refused with a message in the designer's words, and the
// inflation model bounds what `billow inflate` really holds at its peak, without being absurdly cautious.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/mesh_file.hpp"
#include "test_support.hpp"
#include "util/error.hpp"
#include "util/memory_budget.hpp"

namespace billow {
namespace {

TEST(MemoryBudget, ModelsGrowSlightlyFasterThanTheMeshAndOptimizingNeedsMoreThanInflating) {
  double previousPerTriangle = 0;
  for (long long n : {1'000LL, 10'000LL, 100'000LL, 1'000'000LL}) {
    const double bytes = inflationBytes(n);
    EXPECT_GT(bytes, inflationBytes(n / 2)) << n;
    const double perTriangle = (bytes - inflationBytes(0)) / static_cast<double>(n);
    EXPECT_GT(perTriangle, previousPerTriangle) << "the factor's n log n fill";
    EXPECT_LT(perTriangle, 10 * 1024.0) << "about 5 kB per triangle, not more";
    previousPerTriangle = perTriangle;
    EXPECT_GT(optimizationBytes(n, 10'000), 2 * bytes);
    EXPECT_GT(optimizationBytes(n, 500'000), optimizationBytes(n, 10'000)) << "a larger target costs more";
  }
  // What the app allows: the finest resolution fits easily in the 2 GB the page's heap may grow to.
  EXPECT_LT(optimizationBytes(8000, 500'000), 512.0 * 1024 * 1024);
  EXPECT_GT(availableBytes(), 0.0);
}

TEST(MemoryBudget, ANeedOverTheBudgetIsRefusedWithTheSizesAndARemedy) {
  EXPECT_NO_THROW(requireMemory(100e6, 200e6, "Inflating this pattern", "Use fewer triangles."));
  try {
    requireMemory(3.5 * 1024 * 1024 * 1024, 2.0 * 1024 * 1024 * 1024, "Inflating this pattern (700000 triangles)",
                  "Use a pattern with fewer triangles.");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "memory.budget");
    const std::string m = e.what();
    EXPECT_NE(m.find("Inflating this pattern (700000 triangles) needs about 3.5 GB"), std::string::npos) << m;
    EXPECT_NE(m.find("2.0 GB"), std::string::npos) << m;
    EXPECT_NE(m.find("Use a pattern with fewer triangles."), std::string::npos) << m;
  }
  EXPECT_EQ(formatBytes(300.2 * 1024 * 1024), "301 MB");
  EXPECT_EQ(formatBytes(1.25 * 1024 * 1024 * 1024), "1.2 GB");
}

TEST(MemoryBudget, InflationModelBoundsTheCliPeakAndTheCliRefusesOverItsBudget) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  using nlohmann::json;
  const std::string dir = testing::TempDir();
  const std::string pattern = dir + "billow-memory-mylar.json", result = dir + "billow-memory-result.json";
  std::string out;
  ASSERT_EQ(test::runCapture(test::cliPath() + " example mylar --triangles 30000 --out " + pattern, out), 0) << out;
  // Two Newton iterations reach the peak (the Hessian and its factor exist from the first); not settling
  // is exit code 1, and the result is still written.
  test::runCapture(test::cliPath() + " inflate " + pattern + " --max-iterations 2 --quiet --out " + result, out);
  const json r = json::parse(readFileBytes(result));
  const double predicted = r["memory"]["predicted_bytes"].get<double>();
  const double peak = r["memory"]["peak_resident_bytes"].get<double>();
  EXPECT_GT(predicted, peak) << "the prediction must not fall short";
  EXPECT_LT(predicted, 2.5 * peak) << "nor be absurdly cautious";
  // With a budget below the prediction the CLI refuses before work, and says why.
  const int code =
      test::runCapture(test::cliPath() + " inflate " + pattern + " --max-memory 40 --out " + dir + "x.json", out);
  EXPECT_NE(code, 0);
  EXPECT_NE(out.find("needs about"), std::string::npos) << out;
  EXPECT_NE(out.find("this computer has 40 MB"), std::string::npos) << out;
  EXPECT_NE(out.find("fewer triangles"), std::string::npos) << out;
#endif
}

}  // namespace
}  // namespace billow
