// Links against the installed disklab and uses a sequence: exits non-zero if anything is off.
#include <cstdio>

#include <disklab/sequence/sequence.h>

int main() {
  auto seq = disklab::sequence::make_sequence("random", 7);
  const disklab::Point2 p = seq->at(3);
  std::printf("%.17g %.17g\n", p.x, p.y);
  return (p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0) ? 0 : 1;
}
