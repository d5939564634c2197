// How messages show input values and counts.
#include <doctest/doctest.h>

#include "common/quote.h"

using namespace facet;

TEST_CASE("counts in messages take the singular for one and the plural otherwise") {
  CHECK(countOf(0, "sampler") == "0 samplers");
  CHECK(countOf(1, "sampler") == "1 sampler");
  CHECK(countOf(2, "sampler") == "2 samplers");
  CHECK(countOf(1, "vertex", "vertices") == "1 vertex");
  CHECK(countOf(24, "vertex", "vertices") == "24 vertices");
}
