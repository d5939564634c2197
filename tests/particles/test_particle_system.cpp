// The particle system: births and deaths, the cone of initial velocities,
// semi-implicit Euler against closed forms, the ground, colour over life,
// determinism, and the refusals.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
#include "particles/particle_system.h"

using namespace facet;

namespace {

// One particle (one every 8 s, living 6), no drag, no ground, straight along
// `direction` at exactly `speed`: a projectile.
Emitter projectile() {
  Emitter e;
  e.position = {1.0f, 2.0f, 3.0f};
  e.direction = {1.0f, 1.0f, 0.0f};
  e.speed = 5.0f;
  e.speedSpread = 0.0f;
  e.spread = 0.0f;
  e.rate = 0.125f;
  e.lifetime = 6.0f;
  e.drag = 0.0f;
  e.ground = false;
  return e;
}

Particle only(const std::vector<Particle>& particles) {
  REQUIRE(particles.size() == 1);
  return particles[0];
}

// The fixed-step schedule the system promises: k = floor(a/h) full steps,
// then a − k·h, in double.
void schedule(double age, float step, double& k, double& rest) {
  k = std::floor(age / static_cast<double>(step));
  rest = std::max(0.0, age - k * static_cast<double>(step));
}

bool sameBits(const Particle& a, const Particle& b) {
  return a.index == b.index && std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
         std::memcmp(&a.velocity, &b.velocity, sizeof a.velocity) == 0 && std::memcmp(&a.age, &b.age, sizeof a.age) == 0 &&
         std::memcmp(&a.color, &b.color, sizeof a.color) == 0 && std::memcmp(&a.size, &b.size, sizeof a.size) == 0;
}

bool sameBits(const std::vector<Particle>& a, const std::vector<Particle>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!sameBits(a[i], b[i])) return false;
  return true;
}

// Who is alive, by the rule itself: t_n = startTime + n/rate in double, alive when t_n <= T < t_n + lifetime.
std::vector<std::uint64_t> aliveByRule(const Emitter& e, float time) {
  std::vector<std::uint64_t> alive;
  for (std::uint64_t n = 0;; ++n) {
    const double born = static_cast<double>(e.startTime) + static_cast<double>(n) / static_cast<double>(e.rate);
    if (born > time) break;
    if (time < born + static_cast<double>(e.lifetime)) alive.push_back(n);
  }
  return alive;
}

std::string refusal(const Emitter& e, float time, float step) {
  try {
    simulateParticles(e, time, step, "particles.3", 2);
  } catch (const Error& error) {
    return error.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("projectile: the semi-implicit Euler closed form, converging to the parabola as g·t·h/2") {
  const Emitter e = projectile();
  const double g = 9.81, v0 = 5.0 / std::sqrt(2.0);
  // With constant a, v_k = v0 + k·a·h and p_k = p0 + h·Σ_{i=1..k} v_i
  // = p0 + k·h·v0 + a·h²·k(k+1)/2; the partial step r then gives v = v_k + a·r,
  // p = p_k + v·r.
  for (float step : {1.0f / 60.0f, 1.0f / 240.0f, 0.01f}) {
    for (float time : {0.0f, 0.3f, 1.5f, 2.71f}) {
      const Particle p = only(simulateParticles(e, time, step, "particles.0", 1));
      double k, r;
      schedule(time, step, k, r);
      const double h = step;
      const double vk = v0 - k * g * h, pk = 2.0 + k * h * v0 - g * h * h * k * (k + 1.0) / 2.0;
      const double vy = vk - g * r, py = pk + vy * r;
      const double px = 1.0 + (k * h + r) * v0;
      INFO("step ", step, " time ", time);
      CHECK(p.velocity.y == doctest::Approx(vy).epsilon(1e-5));
      CHECK(p.position.y == doctest::Approx(py).epsilon(1e-5));
      CHECK(p.position.x == doctest::Approx(px).epsilon(1e-5));
      CHECK(p.position.z == 3.0f);
      CHECK(p.velocity.x == doctest::Approx(v0).epsilon(1e-6));
    }
  }
  // Against the parabola p0 + v0·t − g·t²/2, with t = k·h + r: the scheme's
  // p is lower by g·(h·k·h + r²)/2, and r² <= r·h, so by at most g·h·(k·h + r)/2
  // = g·t·h/2, equal to it when r = 0. Steps 1/64 .. 1/1024 (exact in float,
  // t = 1.5 a whole number of them) must show exactly that error: first order in h.
  const float time = 1.5f;
  const double parabola = 2.0 + v0 * time - g * time * time / 2.0;
  for (float step : {1.0f / 64.0f, 1.0f / 256.0f, 1.0f / 1024.0f}) {
    const Particle p = only(simulateParticles(e, time, step, "particles.0", 1));
    const double error = parabola - p.position.y, bound = g * time * step / 2.0;
    INFO("step ", step, " error ", error, " bound g·t·h/2 ", bound);
    CHECK(error / bound == doctest::Approx(1.0).epsilon(0.01));
  }
  // A step that does not divide t (a partial last step): within the bound.
  for (float step : {1.0f / 60.0f, 1.0f / 240.0f, 0.007f}) {
    const Particle p = only(simulateParticles(e, 1.37f, step, "particles.0", 1));
    const double t = 1.37f;
    const double error = 2.0 + v0 * t - g * t * t / 2.0 - p.position.y, bound = g * t * step / 2.0;
    INFO("step ", step, " error ", error, " bound ", bound);
    CHECK(error >= -1e-5);
    CHECK(error <= bound + 1e-5);
  }
}

TEST_CASE("drag: the velocity relaxes to the wind, and with gravity to wind + m·g/k") {
  Emitter e = projectile();
  e.gravity = {0.0f, 0.0f, 0.0f};
  e.wind = {3.0f, 0.0f, -1.0f};
  e.mass = 0.01f;
  e.drag = 0.02f;  // k/m = 2 per second
  e.lifetime = 12.0f;
  e.rate = 0.05f;
  const float step = 1.0f / 240.0f;
  const double c = static_cast<double>(e.drag) / static_cast<double>(e.mass), v0 = 5.0 / std::sqrt(2.0);
  // v − w shrinks by (1 − c·h) a full step and (1 − c·r) the partial one;
  // the fixed point v = w + g/c is the analytic terminal velocity.
  for (float time : {0.25f, 1.0f, 3.0f, 9.0f}) {
    const Particle p = only(simulateParticles(e, time, step, "particles.0", 1));
    double k, r;
    schedule(time, step, k, r);
    const double shrink = std::pow(1.0 - c * step, k) * (1.0 - c * r);
    INFO("time ", time);
    CHECK(p.velocity.x == doctest::Approx(3.0 + (v0 - 3.0) * shrink).epsilon(1e-5));
    CHECK(p.velocity.y == doctest::Approx(v0 * shrink).epsilon(1e-5).scale(1.0));
    CHECK(p.velocity.z == doctest::Approx(-1.0 + 1.0 * shrink).epsilon(1e-5));
    CHECK(shrink == doctest::Approx(std::exp(-c * time)).epsilon(0.01 * c * time));  // the exact exp(−c·t) to first order in c·h
  }
  // Float stops v short of its fixed point once c·h·|w − v| is under half an
  // ulp of v: a band of about |v|·2^-24/(c·h), 2e-5 here.
  const float band = glm::length(e.wind) * 0x1p-23f / static_cast<float>(c * step);
  const Particle late = only(simulateParticles(e, 9.0f, step, "particles.0", 1));
  CHECK(glm::length(late.velocity - e.wind) < band);

  e.gravity = {0.0f, -9.81f, 0.0f};
  const glm::vec3 terminal = e.wind + e.mass * e.gravity / e.drag;  // (3, −4.905, −1)
  for (float time : {4.0f, 9.0f}) {
    const Particle p = only(simulateParticles(e, time, step, "particles.0", 1));
    double k, r;
    schedule(time, step, k, r);
    const double start = glm::length(glm::vec3(static_cast<float>(v0), static_cast<float>(v0), 0.0f) - terminal);
    const double bound = start * std::pow(1.0 - c * step, k) * (1.0 - c * r) + glm::length(terminal) * 0x1p-23 / (c * step);
    INFO("time ", time, " distance to terminal ", glm::length(p.velocity - terminal), " bound ", bound);
    CHECK(glm::length(p.velocity - terminal) <= bound);
  }
}

TEST_CASE("ground: never below it, bounces keep restitution times the speed, restitution 0 comes to rest") {
  Emitter e;
  e.position = {0.0f, 1.0f, 0.0f};
  e.groundHeight = 0.5f;
  e.spread = 70.0f;
  e.direction = {0.3f, 1.0f, 0.0f};
  e.rate = 500.0f;
  e.wind = {1.0f, 0.0f, 0.0f};
  int below = 0, total = 0;
  for (float time : {0.5f, 1.0f, 2.0f, 3.3f, 7.0f}) {
    for (const Particle& p : simulateParticles(e, time, kDefaultParticleStep, "particles.0", 2)) {
      ++total;
      if (p.position.y < e.groundHeight) ++below;
    }
  }
  CHECK(total > 4000);
  CHECK(below == 0);

  // A drop from 2 above the ground, sampled every step (h = 1/256 exact, so
  // the sample at j·h is the state after j full steps).
  Emitter drop = projectile();
  drop.speed = 0.0f;
  drop.position = {0.0f, 2.25f, 0.0f};
  drop.ground = true;
  drop.groundHeight = 0.25f;
  drop.restitution = 0.6f;
  drop.friction = 0.0f;
  const float h = 1.0f / 256.0f;
  const double g = 9.81, fall = std::sqrt(2.0 * g * 2.0);  // the analytic impact speed
  Particle before = only(simulateParticles(drop, 0.0f, h, "particles.0", 1));
  bool bounced = false;
  for (int j = 1; j < 256 && !bounced; ++j) {
    const Particle now = only(simulateParticles(drop, static_cast<float>(j) * h, h, "particles.0", 1));
    CHECK(now.position.y >= drop.groundHeight);
    if (now.velocity.y > 0.0f) {
      bounced = true;
      const double incoming = before.velocity.y - g * h;  // this step's velocity before the ground reversed it
      INFO("incoming ", incoming, " analytic ", -fall, " outgoing ", now.velocity.y);
      CHECK(now.velocity.y == doctest::Approx(-incoming * 0.6).epsilon(1e-5));
      // The scheme's impact speed is the parabola's within a step and a half of g·h.
      CHECK(std::abs(-incoming - fall) <= 1.5 * g * h);
      CHECK(std::abs(now.velocity.y - 0.6 * fall) <= 0.6 * 1.5 * g * h);
    }
    before = now;
  }
  CHECK(bounced);

  // Restitution 0 and some friction: it lands, stays on the ground, stops.
  Emitter dead = drop;
  dead.speed = 3.0f;
  dead.direction = {1.0f, 1.0f, 0.5f};
  dead.restitution = 0.0f;
  dead.friction = 0.2f;
  const Particle at3 = only(simulateParticles(dead, 3.0f, kDefaultParticleStep, "particles.0", 1));
  const Particle at4 = only(simulateParticles(dead, 4.0f, kDefaultParticleStep, "particles.0", 1));
  CHECK(at3.position.y == dead.groundHeight);
  CHECK(at3.velocity.y == 0.0f);
  CHECK(glm::length(at3.velocity) < 1e-6f);
  CHECK(glm::length(at4.position - at3.position) < 1e-6f);
  CHECK(at3.position.x > 0.5f);  // it did travel before it stopped
}

TEST_CASE("births and deaths: counts, indices and ages follow t_n = startTime + n/rate") {
  Emitter e;
  e.rate = 37.0f;
  e.lifetime = 1.3f;
  e.startTime = 0.4f;
  e.ground = false;
  for (float time : {0.0f, 0.39f, 0.4f, 0.5f, 1.0f, 1.7f, 1.7000001f, 5.0f, 12.345f, 100.0f}) {
    INFO("time ", time);
    const std::vector<Particle> particles = simulateParticles(e, time, kDefaultParticleStep, "particles.0", 2);
    const std::vector<std::uint64_t> expected = aliveByRule(e, time);
    CHECK(particles.size() == expected.size());
    CHECK(aliveParticleCount(e, time) == expected.size());
    if (time >= e.startTime + e.lifetime) CHECK(std::abs(static_cast<double>(particles.size()) - 37.0 * 1.3) <= 1.0);
    for (std::size_t i = 0; i < particles.size() && i < expected.size(); ++i) {
      CHECK(particles[i].index == expected[i]);
      CHECK(particles[i].age >= 0.0f);
      CHECK(particles[i].age < e.lifetime);
      CHECK(particles[i].age == doctest::Approx(time - (0.4 + static_cast<double>(particles[i].index) / 37.0)).epsilon(1e-5).scale(1.0));
    }
  }
  // Exact edges: one born at T is alive with age 0, one born at T − lifetime has died.
  e.rate = 4.0f;
  e.lifetime = 1.0f;
  e.startTime = 0.0f;
  const std::vector<Particle> edge = simulateParticles(e, 1.0f, kDefaultParticleStep, "particles.0", 1);
  REQUIRE(edge.size() == 4);
  CHECK(edge.front().index == 1);
  CHECK(edge.back().index == 4);
  CHECK(edge.back().age == 0.0f);
  CHECK(aliveParticleCount(e, 1.0f) == 4);
  // Counted without simulating: exactly the frame's limit, and far beyond it.
  e.rate = 4'000'000.0f;
  CHECK(aliveParticleCount(e, 2.0f) == kMaxParticles);
  e.rate = 1e30f;
  CHECK(aliveParticleCount(e, 2.0f) > kMaxParticles);
}

TEST_CASE("cone: initial directions within the spread, uniform over the solid angle, speeds in range") {
  Emitter e;
  e.direction = {1.0f, 2.0f, -0.5f};  // not unit: normalized
  e.gravity = {0.0f, 0.0f, 0.0f};
  e.drag = 0.0f;
  e.ground = false;
  e.rate = 20000.0f;
  e.lifetime = 1.0f;
  const glm::dvec3 axis = glm::normalize(glm::dvec3(e.direction));
  for (float spread : {0.0f, 15.0f, 90.0f, 180.0f}) {
    e.spread = spread;
    const std::vector<Particle> particles = simulateParticles(e, 2.0f, kDefaultParticleStep, "particles.0", 2);  // no force: velocity is the initial one
    REQUIRE(particles.size() == 20000);
    const double n = static_cast<double>(particles.size()), cosSpread = std::cos(spread * 3.14159265358979323846 / 180.0);
    double sumCos = 0.0, sumSin2 = 0.0;
    glm::dvec3 sumPerp(0.0);
    int outside = 0;
    for (const Particle& p : particles) {
      const glm::dvec3 d = glm::normalize(glm::dvec3(p.velocity));
      const double cosine = glm::dot(d, axis);
      if (cosine < cosSpread - 1e-6) ++outside;
      sumCos += cosine;
      sumSin2 += std::max(0.0, 1.0 - cosine * cosine);
      sumPerp += d - cosine * axis;
    }
    // Uniform over the solid angle: cos θ uniform in [cos spread, 1], mean
    // (1 + cos spread)/2, standard deviation (1 − cos spread)/√12, so the
    // mean of N within 5·(1 − cos spread)/√(12N). Uniform in θ instead would
    // give 2/π at 90°, 60 deviations off.
    const double sigmaMean = (1.0 - cosSpread) / std::sqrt(12.0 * n);
    INFO("spread ", spread, " mean cos ", sumCos / n, " expected ", (1.0 + cosSpread) / 2.0, " sigma ", sigmaMean);
    CHECK(outside == 0);
    CHECK(std::abs(sumCos / n - (1.0 + cosSpread) / 2.0) <= 5.0 * sigmaMean + 1e-7);
    // Uniform in azimuth: the mean sideways component vanishes (each of its
    // two components has variance E[sin²θ]/2 per sample).
    CHECK(glm::length(sumPerp / n) <= 5.0 * std::sqrt(sumSin2 / n / n) + 1e-7);
  }
  e.spread = 30.0f;
  e.speed = 4.0f;
  e.speedSpread = 0.5f;
  {
    const std::vector<Particle> particles = simulateParticles(e, 2.0f, kDefaultParticleStep, "particles.0", 2);
    float lo = 1e9f, hi = 0.0f;
    double sum = 0.0;
    for (const Particle& p : particles) {
      const float s = glm::length(p.velocity);
      lo = std::min(lo, s), hi = std::max(hi, s), sum += s;
    }
    CHECK(lo >= 3.5f - 1e-5f);
    CHECK(hi <= 4.5f + 1e-5f);
    CHECK(lo < 3.51f);
    CHECK(hi > 4.49f);
    CHECK(std::abs(sum / 20000.0 - 4.0) <= 5.0 * 0.5 / std::sqrt(3.0 * 20000.0));
  }
  // Clamped at 0: speeds in [−0.3, 0.7] become 0 three times in ten.
  e.speed = 0.2f;
  {
    const std::vector<Particle> particles = simulateParticles(e, 2.0f, kDefaultParticleStep, "particles.0", 2);
    int zero = 0;
    float hi = 0.0f;
    for (const Particle& p : particles) {
      const float s = glm::length(p.velocity);
      if (s == 0.0f) ++zero;
      hi = std::max(hi, s);
    }
    CHECK(hi <= 0.7f + 1e-6f);
    CHECK(std::abs(zero / 20000.0 - 0.3) <= 5.0 * std::sqrt(0.3 * 0.7 / 20000.0));
  }
}

TEST_CASE("determinism: any thread count, the same seed, and particle n alone decide particle n") {
  Emitter e;
  e.rate = 4000.0f;
  e.wind = {1.0f, 0.0f, 0.5f};
  e.drag = 0.004f;
  const float time = 3.3f;
  const std::vector<Particle> one = simulateParticles(e, time, kDefaultParticleStep, "particles.0", 1);
  REQUIRE(one.size() == 10000);
  CHECK(sameBits(one, simulateParticles(e, time, kDefaultParticleStep, "particles.0", 2)));
  CHECK(sameBits(one, simulateParticles(e, time, kDefaultParticleStep, "particles.0", 7)));
  CHECK(sameBits(one, simulateParticles(e, time, kDefaultParticleStep, "particles.0", 0)));
  CHECK(sameBits(one, simulateParticles(e, time, kDefaultParticleStep, "particles.0", 1)));

  Emitter other = e;
  other.seed = 2;
  const std::vector<Particle> reseeded = simulateParticles(other, time, kDefaultParticleStep, "particles.0", 2);
  REQUIRE(reseeded.size() == one.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < one.size(); ++i)
    if (one[i].position != reseeded[i].position) ++differ;
  CHECK(differ > one.size() * 99 / 100);

  // Particle n does not depend on how many others are alive: a shorter life
  // leaves the survivors' motion bit for bit.
  Emitter shortLived = e;
  shortLived.lifetime = 0.7f;
  const std::vector<Particle> few = simulateParticles(shortLived, time, kDefaultParticleStep, "particles.0", 3);
  REQUIRE(!few.empty());
  REQUIRE(few.size() < one.size() / 2);
  const std::uint64_t offset = few.front().index - one.front().index;
  int moved = 0;
  for (const Particle& p : few) {
    const Particle& q = one[p.index - one.front().index];
    if (p.index != q.index || std::memcmp(&p.position, &q.position, sizeof p.position) || std::memcmp(&p.velocity, &q.velocity, sizeof p.velocity)) ++moved;
  }
  CHECK(offset > 0);
  CHECK(moved == 0);

  // Starting later by Δ and looking later by Δ shows the same particles (times exact in binary).
  Emitter early = e, late = e;
  early.rate = late.rate = 64.0f;
  late.startTime = 0.75f;
  const std::vector<Particle> a = simulateParticles(early, 2.0f, kDefaultParticleStep, "particles.0", 2);
  const std::vector<Particle> b = simulateParticles(late, 2.75f, kDefaultParticleStep, "particles.0", 1);
  REQUIRE(a.size() == b.size());
  CHECK(sameBits(a, b));
}

TEST_CASE("colour, alpha and size: linear in age over lifetime") {
  Emitter e;
  e.rate = 1024.0f;
  e.lifetime = 0.5f;
  e.startColor = {0.6f, 0.8f, 1.0f};
  e.endColor = {0.1f, 0.3f, 0.9f};
  e.startAlpha = 0.9f, e.endAlpha = 0.0f;
  e.startSize = 0.08f, e.endSize = 0.16f;
  const std::vector<Particle> particles = simulateParticles(e, 1.0f, kDefaultParticleStep, "particles.0", 1);
  REQUIRE(particles.size() == 512);
  const Particle& newborn = particles.back();  // n = 1024, born at T exactly
  CHECK(newborn.age == 0.0f);
  CHECK(newborn.color == glm::vec4(e.startColor, e.startAlpha));
  CHECK(newborn.size == e.startSize);

  const Particle& oldest = particles.front();  // n = 513, age 511/1024: t = 511/512
  CHECK(oldest.index == 513);
  const double t = 511.0 / 512.0;
  for (int c = 0; c < 3; ++c) {
    CHECK(oldest.color[c] == doctest::Approx(e.startColor[c] + (e.endColor[c] - e.startColor[c]) * t).epsilon(1e-6));
    CHECK(std::abs(oldest.color[c] - e.endColor[c]) <= 0.002f * std::abs(e.endColor[c] - e.startColor[c]) + 1e-6f);
  }
  CHECK(oldest.color.a == doctest::Approx(0.9 * (1.0 - t)).epsilon(1e-6));
  CHECK(oldest.size == doctest::Approx(0.08 + 0.08 * t).epsilon(1e-6));

  const Particle& middle = particles[768 - 513];  // age 0.25: halfway
  CHECK(middle.index == 768);
  CHECK(middle.color.r == doctest::Approx(0.35f));
  CHECK(middle.color.a == doctest::Approx(0.45f));
  CHECK(middle.size == doctest::Approx(0.12f));
}

TEST_CASE("refusals: each names its key in one line") {
  const Emitter good = projectile();
  CHECK(refusal(good, 1.0f, kDefaultParticleStep) == "(accepted)");
  const float nan = std::nanf(""), inf = INFINITY;
  struct Case {
    const char* key;
    Emitter e;
    float time, step;
  };
  std::vector<Case> cases;
  const auto add = [&](const char* key, auto change, float time = 1.0f, float step = kDefaultParticleStep) {
    Emitter e = good;
    change(e);
    cases.push_back({key, e, time, step});
  };
  const auto same = [](Emitter&) {};
  add("time", same, -1.0f);
  add("time", same, nan);
  add("time", same, inf);
  add("particles.3.step", same, 1.0f, 0.0f);
  add("particles.3.step", same, 1.0f, -0.01f);
  add("particles.3.step", same, 1.0f, nan);
  add("particles.3.step", same, 1.0f, inf);
  add("particles.3.step", [](Emitter& e) { e.lifetime = 1000.0f; }, 1.0f, 1e-5f);  // 10^8 steps a particle
  add("particles.3.position", [&](Emitter& e) { e.position.y = inf; });
  add("particles.3.rate", [](Emitter& e) { e.rate = 0.0f; });
  add("particles.3.rate", [](Emitter& e) { e.rate = -5.0f; });
  add("particles.3.rate", [&](Emitter& e) { e.rate = inf; });
  add("particles.3.rate", [&](Emitter& e) { e.rate = nan; });
  add("particles.3.startTime", [&](Emitter& e) { e.startTime = nan; });
  add("particles.3.direction", [](Emitter& e) { e.direction = {0.0f, 0.0f, 0.0f}; });
  add("particles.3.direction", [&](Emitter& e) { e.direction.x = nan; });
  add("particles.3.spread", [](Emitter& e) { e.spread = -1.0f; });
  add("particles.3.spread", [](Emitter& e) { e.spread = 181.0f; });
  add("particles.3.speed", [](Emitter& e) { e.speed = -1.0f; });
  add("particles.3.speedSpread", [](Emitter& e) { e.speedSpread = -0.1f; });
  add("particles.3.lifetime", [](Emitter& e) { e.lifetime = 0.0f; });
  add("particles.3.lifetime", [](Emitter& e) { e.lifetime = -1.0f; });
  add("particles.3.startColor", [&](Emitter& e) { e.startColor.g = nan; });
  add("particles.3.endColor", [&](Emitter& e) { e.endColor.b = inf; });
  add("particles.3.startAlpha", [](Emitter& e) { e.startAlpha = 1.5f; });
  add("particles.3.endSize", [](Emitter& e) { e.endSize = -0.1f; });
  add("particles.3.mass", [](Emitter& e) { e.mass = 0.0f; });
  add("particles.3.mass", [](Emitter& e) { e.mass = -1.0f; });
  add("particles.3.gravity", [&](Emitter& e) { e.gravity.y = nan; });
  add("particles.3.drag", [](Emitter& e) { e.drag = -0.1f; });
  add("particles.3.drag", [](Emitter& e) { e.drag = 10.0f, e.mass = 0.01f; });  // (k/m)·h = 4.2: the step overshoots
  add("particles.3.wind", [&](Emitter& e) { e.wind.z = -inf; });
  add("particles.3.groundHeight", [&](Emitter& e) { e.groundHeight = nan; });
  add("particles.3.restitution", [](Emitter& e) { e.restitution = 1.5f; });
  add("particles.3.restitution", [](Emitter& e) { e.restitution = -0.1f; });
  add("particles.3.friction", [](Emitter& e) { e.friction = 2.0f; });
  add("particles.3.friction", [](Emitter& e) { e.friction = -0.5f; });
  add("particles.3.rate", [](Emitter& e) { e.rate = 4'000'001.0f, e.lifetime = 1.0f; }, 2.0f);  // one over the frame's limit
  add("particles.3.rate", [](Emitter& e) { e.rate = 1e6f, e.lifetime = 0.001f; }, 1e10f);  // past 2^52 births
  add("particles.3", [](Emitter& e) { e.gravity.y = -3e38f; }, 5.0f);  // the motion overflows float
  for (const Case& c : cases) {
    const std::string message = refusal(c.e, c.time, c.step);
    INFO(c.key, ": ", message);
    CHECK(message.rfind(std::string(c.key) + ": ", 0) == 0);
    CHECK(message.find('\n') == std::string::npos);
  }
}

TEST_CASE("refusals: 10^9 particles a second are refused before anything is allocated") {
  Emitter e = projectile();
  e.rate = 1e9f;
  e.lifetime = 1.0f;
  const auto start = std::chrono::steady_clock::now();
  // Allocating first would throw std::bad_alloc (56 GB) or take seconds to fill, not this Error.
  const std::string message = refusal(e, 5.0f, kDefaultParticleStep);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(message == "particles.3.rate: 1e+09 particles a second live 1 s: 1000000000 alive, more than the 4000000 a frame may hold");
  CHECK(seconds < 0.1);
  CHECK(aliveParticleCount(e, 5.0f) == 1'000'000'000);
}
