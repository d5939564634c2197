#pragma once
// Every primitive, in index order, with the same primitive tests the BVH
// uses: what the BVH must reproduce exactly (the same primitive, the same t,
// u, v bits; tests/ray/test_bvh.cpp). Primitives without finite bounds are
// skipped, as the BVH leaves them out (primitives.h).
#include "ray/primitives.h"
#include "ray/ray.h"

namespace facet::ray {

// The nearest hit in (tMin, tMax) by nearer() (ray.h); false when none.
bool intersectBruteForce(const Primitives& primitives, const Ray& ray, Hit& hit);

// Whether anything is hit in (tMin, tMax).
bool occludedBruteForce(const Primitives& primitives, const Ray& ray);

}  // namespace facet::ray
