// The streaming compensator allocates nothing per sample (docs/architecture.md, invariants). A
// program of its own: it replaces the global allocation functions to count calls, which must not
// touch the main suite. Every non-aligned form is replaced, so allocation and release always pair.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "fogdrift/regress/mlp.hpp"
#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/train/train.hpp"
#include "synthetic_dataset.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void* counted(std::size_t size) {
  if (g_counting) ++g_allocations;
  return std::malloc(size ? size : 1);
}
}  // namespace

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  if (void* p = counted(n)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  if (void* p = counted(n)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return counted(n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return counted(n);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace fogdrift {
namespace {

TEST(StreamingCompensator, AllocatesNothingPerSample) {
  // Three features named like temperatures; the synthetic rows stand in for logger samples.
  Dataset data = test::synthetic();
  DatasetOptions dataset;
  dataset.features = FeatureSpec::parse("T");
  data.feature_names = dataset.features.names();
  for (Method method : {Method::svr, Method::bp, Method::poly}) {
    TrainOptions o;
    o.method = method;
    o.trainers.get<MlpOptions>().max_epochs = 50;
    const CompensationModel model = train(data, dataset, o).model;
    StreamingCompensator stream(model, 1.0);
    double sum = 0;
    g_allocations = 0;
    g_counting = true;
    for (std::size_t i = 0; i < data.rows; ++i) {
      const auto r = data.row(i);
      sum += stream.update({static_cast<double>(i), 0.0, r[0], r[1], r[2]}).drift_dph;
    }
    // The fault policy's paths allocate nothing either: NaN readings, a stuck-free outage long
    // enough to stop the correction, bridged and long gaps, a sample out of order, a restart.
    const double nan = std::nan("");
    double t = 0;
    for (std::size_t i = 0; i < data.rows; ++i) {
      const auto r = data.row(i);
      t += i % 97 == 5 ? 4.0 : (i % 193 == 7 ? 30.0 : (i % 211 == 9 ? -0.5 : 1.0));
      if (i == data.rows / 2) t = 0;
      const bool out = i % 300 > 200 && i % 300 < 280;
      sum += stream.update({t, i % 13 == 0 ? nan : 0.0, out ? nan : r[0], r[1], r[2]}).drift_dph;
    }
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << to_string(method);
    EXPECT_TRUE(std::isfinite(sum));
  }
}

}  // namespace
}  // namespace fogdrift
