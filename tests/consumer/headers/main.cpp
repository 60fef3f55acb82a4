// Reached only when every installed header compiled on its own (CMakeLists.txt beside).
#include <cstdio>

int main() {
  std::printf("%d installed headers each compile on their own\n", HEADER_COUNT);
  return 0;
}
