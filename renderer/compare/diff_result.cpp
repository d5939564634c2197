#include "compare/diff_result.h"

#include <algorithm>

namespace facet {

void PixelBox::add(int x, int y) {
  minX = std::min(minX, x);
  minY = std::min(minY, y);
  maxX = std::max(maxX, x);
  maxY = std::max(maxY, y);
}

}  // namespace facet
