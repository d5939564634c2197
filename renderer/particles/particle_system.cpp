// The particle system (renderer/PIPELINE.md, "Particle systems"): who is alive at T, each particle's seeded start, its fixed-step integration.
#include "particles/particle_system.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <new>
#include <numbers>
#include <string>
#include <thread>

#include "common/error.h"
#include "common/random.h"
#include "common/denormals.h"  // header only: the mode the CPU backend and llvmpipe compute in
#include "settings/settings_fields.h"

namespace facet {
namespace {

// Indices stay at most 2^52, where double(n) is exact: birth times then
// never decrease with n, and the search for the alive range is exact.
constexpr std::uint64_t kMaxParticleIndex = std::uint64_t{1} << 52;
// The particles each lane group integrates in lockstep (one AVX register of floats).
constexpr int kLanes = 8;
// A worker costs more to start than this many particles do to integrate.
constexpr std::uint64_t kMinParticlesPerWorker = 256;

// An input as written (its shortest float), and a derived figure to 6 digits.
std::string number(float v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}
std::string number(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v, std::chars_format::general, 6).ptr;
  return std::string(text, end);
}

std::string vec3(glm::vec3 v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// ---- Who is alive: t_n = startTime + n / rate, alive when t_n <= T < t_n + lifetime, in double.

double birthTime(const Emitter& e, std::uint64_t n) { return static_cast<double>(e.startTime) + static_cast<double>(n) / static_cast<double>(e.rate); }
// The two halves of the one test of who is alive; each is monotone in n.
bool bornBy(const Emitter& e, std::uint64_t n, double time) { return birthTime(e, n) <= time; }
bool deadBy(const Emitter& e, std::uint64_t n, double time) { return !(time < birthTime(e, n) + static_cast<double>(e.lifetime)); }

// The smallest n in [0, limit] where `holds` is false, for a predicate true up
// to some n and false after (limit + 1 when it holds throughout). Gallops
// from `guess`, the formula's estimate, then bisects: O(log) evaluations of
// the same predicate whatever the rounding of the estimate.
template <class Holds>
std::uint64_t firstFailing(Holds holds, double guess, std::uint64_t limit) {
  std::uint64_t known = !(guess > 0.0) ? 0 : guess >= static_cast<double>(limit) ? limit : static_cast<std::uint64_t>(guess);
  std::uint64_t lo = 0, hi = 0, stride = 1;  // the answer is in [lo, hi]
  if (holds(known)) {
    for (;; stride *= 2) {
      if (known == limit) return limit + 1;
      const std::uint64_t probe = known + std::min(stride, limit - known);
      if (!holds(probe)) {
        lo = known + 1, hi = probe;
        break;
      }
      known = probe;
    }
  } else {
    for (;; stride *= 2) {
      if (known == 0) return 0;
      const std::uint64_t probe = known - std::min(stride, known);
      if (holds(probe)) {
        lo = probe + 1, hi = known;
        break;
      }
      known = probe;
    }
  }
  while (lo < hi) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    if (holds(mid)) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

struct AliveRange {
  std::uint64_t first = 0, end = 0;  // alive: first <= n < end
  bool indexable = true;             // false: more than 2^52 born by T, [first, end) not computed
};

// Needs rate > 0 and every value finite. A particle dead by T was born by T
// (lifetime > 0), so first <= end.
AliveRange aliveRange(const Emitter& e, double time) {
  const double rate = e.rate, start = e.startTime, lifetime = e.lifetime;
  AliveRange r;
  r.end = firstFailing([&](std::uint64_t n) { return bornBy(e, n, time); }, (time - start) * rate + 1.0, kMaxParticleIndex);
  if (r.end > kMaxParticleIndex) return {0, 0, false};
  r.first = firstFailing([&](std::uint64_t n) { return deadBy(e, n, time); }, (time - start - lifetime) * rate + 1.0, r.end);
  return r;
}

bool countable(const Emitter& e, float time) {
  return std::isfinite(time) && std::isfinite(e.rate) && e.rate > 0.0f && std::isfinite(e.startTime) && std::isfinite(e.lifetime) && e.lifetime > 0.0f;
}

// ---- Each particle's random numbers: common/random.h's SplitMix64 started
// from a hash of (seed, n) alone, so no particle's numbers depend on
// another's or on which thread draws them.

SplitMix64 particleRandom(int seed, std::uint64_t n) {
  return SplitMix64(mix64(mix64(std::uint64_t{static_cast<std::uint32_t>(seed)} ^ 0x5851F42D4C957F2Dull) ^ n));
}

// The cone of initial directions, in double: the unit axis, a frame
// completing it (Duff et al. 2017), and 1 − cos(spread) = 2 sin²(spread/2)
// without cancellation at small angles.
struct Cone {
  double w[3], a[3], b[3];
  double oneMinusCosSpread;
};

Cone makeCone(const Emitter& e) {
  Cone c;
  const double x = e.direction.x, y = e.direction.y, z = e.direction.z;
  const double length = std::sqrt(x * x + y * y + z * z);
  c.w[0] = x / length, c.w[1] = y / length, c.w[2] = z / length;
  const double sign = std::copysign(1.0, c.w[2]);
  const double p = -1.0 / (sign + c.w[2]), q = c.w[0] * c.w[1] * p;
  c.a[0] = 1.0 + sign * c.w[0] * c.w[0] * p, c.a[1] = sign * q, c.a[2] = -sign * c.w[0];
  c.b[0] = q, c.b[1] = sign + c.w[1] * c.w[1] * p, c.b[2] = -c.w[1];
  const double half = static_cast<double>(e.spread) * std::numbers::pi / 360.0;
  c.oneMinusCosSpread = 2.0 * std::sin(half) * std::sin(half);
  return c;
}

// Particle n's initial velocity: a direction uniform over the cone's solid
// angle (1 − cos θ = u₁·(1 − cos spread), φ = 2π·u₂) times a speed uniform in
// [speed − speedSpread, speed + speedSpread] (speed + speedSpread·(2u₃ − 1)), clamped at 0.
glm::vec3 initialVelocity(const Emitter& e, const Cone& c, std::uint64_t n) {
  SplitMix64 random = particleRandom(e.seed, n);
  const double oneMinusCos = random.unitDouble() * c.oneMinusCosSpread;
  const double phi = 2.0 * std::numbers::pi * random.unitDouble();
  const double speed = std::max(0.0, static_cast<double>(e.speed) + static_cast<double>(e.speedSpread) * (2.0 * random.unitDouble() - 1.0));
  const double cosTheta = 1.0 - oneMinusCos, sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
  const double along = sinTheta * std::cos(phi), across = sinTheta * std::sin(phi);
  glm::vec3 v;
  for (int k = 0; k < 3; ++k) v[k] = static_cast<float>(speed * (along * c.a[k] + across * c.b[k] + cosTheta * c.w[k]));
  return v;
}

// ---- Integration, in float, every operation in the written order (the
// build contracts nothing into fused multiply-adds).

struct Forces {
  float gx, gy, gz;              // gravity
  float dragPerMass;             // k / m, 1/s
  float wx, wy, wz;              // wind
  float ground, restitution, keep;  // keep = 1 − friction
};

// mask ? a : b on the bits. GCC (with the default -ftrapping-math) will not
// turn a floating-point ?: whose arms it sinks into branches back into
// vector selects; integer bit operations it will.
inline float choose(std::uint32_t mask, float a, float b) {
  return std::bit_cast<float>((std::bit_cast<std::uint32_t>(a) & mask) | (std::bit_cast<std::uint32_t>(b) & ~mask));
}

// One semi-implicit Euler step of length dt (the course's particle step):
// a = g + (k/m)·(wind − v); v += a·dt; p += v·dt; then the ground: below it,
// p.y is mirrored up by restitution, v.y reversed and scaled by restitution,
// v.x and v.z scaled by 1 − friction. Selects, not branches, so that the
// lane loop vectorizes; the values are the branch's.
template <bool kGround>
inline void advance(float& px, float& py, float& pz, float& vx, float& vy, float& vz, float dt, const Forces f) {
  const float ax = f.gx + f.dragPerMass * (f.wx - vx);
  const float ay = f.gy + f.dragPerMass * (f.wy - vy);
  const float az = f.gz + f.dragPerMass * (f.wz - vz);
  vx = vx + ax * dt;
  vy = vy + ay * dt;
  vz = vz + az * dt;
  px = px + vx * dt;
  py = py + vy * dt;
  pz = pz + vz * dt;
  if constexpr (kGround) {
    const bool below = py < f.ground;
    const float mirrored = f.ground + (f.ground - py) * f.restitution, reversed = -vy * f.restitution;
    const float keptX = vx * f.keep, keptZ = vz * f.keep;
    const std::uint32_t mask = 0u - static_cast<std::uint32_t>(below);
    py = choose(mask, mirrored, py);
    vy = choose(mask, reversed, vy);
    vx = choose(mask, keptX, vx);
    vz = choose(mask, keptZ, vz);
  }
}

struct Job {
  const Emitter* emitter;
  Cone cone;
  Forces forces;
  double time, step;
  std::uint64_t first;  // the index of out[0]
  Particle* out;
};

// Particles [from, to) of the job (offsets into out). Groups of kLanes run
// their common full steps in lockstep, then each its own remaining full
// steps and the partial one: the same operations on each particle as one at
// a time, so neither the grouping nor the split over workers changes a bit.
template <bool kGround>
void integrate(const Job& job, std::uint64_t from, std::uint64_t to) {
  const Emitter& e = *job.emitter;
  const Forces f = job.forces;  // a local copy: the lane loop keeps it in registers
  const float h = static_cast<float>(job.step);
  for (std::uint64_t g = from; g < to; g += kLanes) {
    const int lanes = static_cast<int>(std::min<std::uint64_t>(kLanes, to - g));
    float px[kLanes], py[kLanes], pz[kLanes], vx[kLanes], vy[kLanes], vz[kLanes], rest[kLanes];
    double age[kLanes];
    std::uint64_t steps[kLanes];
    std::uint64_t common = std::numeric_limits<std::uint64_t>::max();
    for (int l = 0; l < kLanes; ++l) {
      const std::uint64_t n = job.first + g + static_cast<std::uint64_t>(std::min(l, lanes - 1));  // padding lanes repeat the last
      // Age a = T − t_n; k = floor(a/h) full steps, then a − k·h (a rounding
      // below 0 taken as 0), all in double; the partial step's length rounded to float.
      age[l] = job.time - birthTime(e, n);
      const double k = std::floor(age[l] / job.step);
      steps[l] = static_cast<std::uint64_t>(k);
      rest[l] = static_cast<float>(std::max(0.0, age[l] - k * job.step));
      const glm::vec3 v = initialVelocity(e, job.cone, n);
      px[l] = e.position.x, py[l] = e.position.y, pz[l] = e.position.z;
      vx[l] = v.x, vy[l] = v.y, vz[l] = v.z;
      common = std::min(common, steps[l]);
    }
    for (std::uint64_t s = 0; s < common; ++s)
      for (int l = 0; l < kLanes; ++l) advance<kGround>(px[l], py[l], pz[l], vx[l], vy[l], vz[l], h, f);
    for (int l = 0; l < lanes; ++l) {
      for (std::uint64_t s = common; s < steps[l]; ++s) advance<kGround>(px[l], py[l], pz[l], vx[l], vy[l], vz[l], h, f);
      advance<kGround>(px[l], py[l], pz[l], vx[l], vy[l], vz[l], rest[l], f);
      Particle& out = job.out[g + static_cast<std::uint64_t>(l)];
      out.index = job.first + g + static_cast<std::uint64_t>(l);
      out.position = {px[l], py[l], pz[l]};
      out.velocity = {vx[l], vy[l], vz[l]};
      // In [0, lifetime): a double age just below it may round up to it in float.
      out.age = std::min(static_cast<float>(age[l]), std::nextafter(e.lifetime, 0.0f));
      // Linear in age / lifetime: start + (end − start)·t, in float.
      const float t = out.age / e.lifetime;
      for (int c = 0; c < 3; ++c) out.color[c] = e.startColor[c] + (e.endColor[c] - e.startColor[c]) * t;
      out.color.a = e.startAlpha + (e.endAlpha - e.startAlpha) * t;
      out.size = e.startSize + (e.endSize - e.startSize) * t;
    }
  }
}

// Every worker, the calling thread included, integrates with denormals
// flushed to zero, whatever mode its thread had: the same bits on any
// thread, and no slow denormal arithmetic as a resting particle's speed decays.
void runRange(const Job& job, std::uint64_t from, std::uint64_t to) {
  const FlushDenormals flush;
  if (job.emitter->ground) integrate<true>(job, from, to);
  else integrate<false>(job, from, to);
}

// ---- Validation: one line naming the key of the value at fault.

// Every number of the emitter against its range in the settings' field table
// (settings/settings_fields.h), the one its key is read with, so the two
// cannot disagree; a number the table leaves unbounded must be finite. The
// bounds are compared as floats: the settings check the double they read,
// then narrow it, and narrowing keeps order, so whatever they accept passes here.
struct TableRanges {
  const std::string& key;

  std::string name(const FieldInfo& f) const { return key + "." + std::string(f.key); }
  bool bounded(const FieldInfo& f) const { return f.min != f.max; }
  bool inRange(const FieldInfo& f, float v) const { return v >= static_cast<float>(f.min) && v <= static_cast<float>(f.max); }
  std::string range(const FieldInfo& f) const {
    return "[" + number(static_cast<float>(f.min)) + ", " + number(static_cast<float>(f.max)) + "]";
  }

  void field(const FieldInfo& f, float v) {
    if (!bounded(f) && !std::isfinite(v)) throw Error(name(f) + ": " + number(v) + " is not finite");
    if (bounded(f) && !inRange(f, v))
      throw Error(name(f) + ": " + number(v) + (f.unit.empty() ? "" : " ") + std::string(f.unit) + " is outside " + range(f));
  }
  void field(const FieldInfo& f, glm::vec3 v) {
    if (!bounded(f) && !finite(v)) throw Error(name(f) + ": " + vec3(v) + " is not finite");
    if (bounded(f) && !(inRange(f, v.x) && inRange(f, v.y) && inRange(f, v.z))) throw Error(name(f) + ": " + vec3(v) + " is outside " + range(f));
  }
  void field(const FieldInfo& f, int v) {
    if (bounded(f) && !(v >= f.min && v <= f.max)) throw Error(name(f) + ": " + std::to_string(v) + " is outside " + range(f));
  }
  void field(const FieldInfo&, bool) {}
  void field(const FieldInfo&, const std::string&) {}
  template <class E, std::size_t N>
  void choice(const FieldInfo&, E, const std::array<std::string_view, N>&) {}
};

// The time, then the emitter (checkEmitter).
void validate(const Emitter& e, float time, float step, const std::string& key) {
  if (!std::isfinite(time)) throw Error("time: " + number(time) + " is not a finite number of seconds");
  if (time < 0.0f) throw Error("time: " + number(time) + " s is before 0");
  checkEmitter(e, step, key);
}

}  // namespace

// The table's ranges first (with `step`, the step the particles are integrated
// with, as the emitter's), then what no range can say.
void checkEmitter(const Emitter& e, float step, const std::string& key) {
  Emitter checked = e;
  checked.step = step;
  TableRanges ranges{key};
  visitItem(ranges, checked);

  if (e.direction == glm::vec3(0.0f)) throw Error(key + ".direction: (0, 0, 0) has no direction");
  const double stepsPerParticle = static_cast<double>(e.lifetime) / static_cast<double>(step);
  if (stepsPerParticle > kMaxStepsPerParticle)
    throw Error(key + ".step: " + number(step) + " s over " + key + ".lifetime " + number(e.lifetime) + " s is " + number(stepsPerParticle) +
                " steps a particle, more than " + std::to_string(static_cast<std::uint64_t>(kMaxStepsPerParticle)));
  // Explicit Euler on the drag: (k/m)·h > 1 overshoots the wind's velocity
  // each step (and diverges past 2), so the motion would be the step's, not the drag's.
  const double dragStep = static_cast<double>(e.drag) / static_cast<double>(e.mass) * static_cast<double>(step);
  if (dragStep > 1.0)
    throw Error(key + ".drag: " + number(e.drag) + " kg/s over " + key + ".mass " + number(e.mass) + " kg times " + key + ".step " + number(step) +
                " s is " + number(dragStep) + ", more than 1: the step overshoots the wind's velocity");
}

std::uint64_t aliveParticleCount(const Emitter& emitter, float time) {
  // An emitter simulateParticles refuses for its rate, startTime or lifetime (or a time not finite) has none.
  if (!countable(emitter, time)) return 0;
  const AliveRange r = aliveRange(emitter, time);
  if (r.indexable) return r.end - r.first;
  // More than 2^52 born: the formula, rate × the span of birth times alive, saturated.
  const double span = std::min(static_cast<double>(emitter.lifetime), static_cast<double>(time) - static_cast<double>(emitter.startTime));
  const double count = std::floor(span * static_cast<double>(emitter.rate)) + 1.0;
  return count >= 0x1p64 ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(count);
}

std::vector<Particle> simulateParticles(const Emitter& emitter, float time, float step, const char* key, int threads) {
  const std::string name = key;
  validate(emitter, time, step, name);

  // How many, counted before anything is allocated.
  const std::uint64_t count = aliveParticleCount(emitter, time);
  if (count > kMaxParticles)
    throw Error(name + ".rate: " + number(emitter.rate) + " particles a second live " + number(emitter.lifetime) + " s: " + std::to_string(count) +
                " alive, more than the " + std::to_string(kMaxParticles) + " a frame may hold");
  const AliveRange range = aliveRange(emitter, time);
  if (!range.indexable)
    throw Error(name + ".rate: " + number(emitter.rate) + " particles a second from " + name + ".startTime " + number(emitter.startTime) +
                " s bear more than 2^52 particles by time " + number(time) + " s, past which their birth times are not exact");
  // The work, priced before it starts: births are evenly spaced, so the
  // steps are the count times the mean of the oldest and youngest ages.
  if (count > 0) {
    const double oldest = static_cast<double>(time) - birthTime(emitter, range.first);
    const double youngest = static_cast<double>(time) - birthTime(emitter, range.end - 1);
    const double steps = static_cast<double>(count) * (oldest + youngest) / 2.0 / static_cast<double>(step);
    if (steps > kMaxParticleSteps)
      throw Error(name + ": " + std::to_string(count) + " particles alive at time " + number(time) + " s, integrated with " + name + ".step " +
                  number(step) + " s, take " + number(steps) + " steps, more than the " + number(kMaxParticleSteps) +
                  " a frame may take; a larger step, a shorter lifetime or a lower rate takes fewer");
  }

  std::vector<Particle> particles;
  try {
    particles.resize(count);
  } catch (const std::bad_alloc&) {
    throw OutOfMemory("simulating " + std::to_string(count) + " particles of " + name);
  }
  if (count == 0) return particles;

  Job job{&emitter,
          makeCone(emitter),
          Forces{emitter.gravity.x, emitter.gravity.y, emitter.gravity.z, emitter.drag / emitter.mass, emitter.wind.x, emitter.wind.y, emitter.wind.z,
                 emitter.groundHeight, emitter.restitution, 1.0f - emitter.friction},
          static_cast<double>(time),
          static_cast<double>(step),
          range.first,
          particles.data()};

  // Contiguous ranges of about equal work: a particle costs its steps, about
  // age / step, and the oldest come first. Boundaries fall on lane groups;
  // where they fall changes no result.
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::uint64_t wanted = threads > 0 ? static_cast<std::uint64_t>(threads) : hardware;
  const std::uint64_t workers = std::max<std::uint64_t>(1, std::min(wanted, count / kMinParticlesPerWorker));
  const auto cost = [&](std::uint64_t i) { return (time - birthTime(emitter, range.first + i)) / job.step + 16.0; };
  std::vector<std::uint64_t> bounds{0};
  if (workers > 1) {
    const std::uint64_t groups = (count + kLanes - 1) / kLanes;
    double total = 0.0;
    for (std::uint64_t g = 0; g < groups; ++g) total += cost(g * kLanes);
    double sum = 0.0;
    for (std::uint64_t g = 0; g < groups && bounds.size() < workers; ++g) {
      sum += cost(g * kLanes);
      if (sum >= total * static_cast<double>(bounds.size()) / static_cast<double>(workers)) bounds.push_back((g + 1) * kLanes);
    }
  }
  bounds.push_back(count);
  for (std::uint64_t& b : bounds) b = std::min(b, count);

  // A worker that cannot be started has its range run here instead: the same result.
  std::vector<std::thread> pool;
  pool.reserve(bounds.size());
  std::vector<std::size_t> here{0};
  for (std::size_t w = 1; w + 1 < bounds.size(); ++w) {
    try {
      pool.emplace_back(runRange, std::cref(job), bounds[w], bounds[w + 1]);
    } catch (...) {
      here.push_back(w);
    }
  }
  for (std::size_t w : here) runRange(job, bounds[w], bounds[w + 1]);
  for (std::thread& t : pool) t.join();

  for (const Particle& p : particles)
    if (!finite(p.position) || !finite(p.velocity))
      throw Error(name + ": particle " + std::to_string(p.index) + " at time " + number(time) + " s is at " + vec3(p.position) + " moving " +
                  vec3(p.velocity) + ": the forces or speeds leave float's range");
  return particles;
}

}  // namespace facet
