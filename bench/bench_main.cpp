// Native benchmarks (see bench/README.md). Filled in by the simulator and optimizer issues.
#include <cstdio>
int main() {
  std::printf("billow native benchmarks: none yet\n");
  return 0;
}
