// The streaming compensator allocates nothing per sample (docs/architecture.md, invariants). A
// program of its own: it replaces the global allocation functions to count calls, which must not
// touch the main suite. Every non-aligned form is replaced, so allocation and release always pair.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "fogdrift/compensator.hpp"
#include "fogdrift/train.hpp"
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
    o.mlp.max_epochs = 50;
    const CompensationModel model = train(data, dataset, o).model;
    StreamingCompensator stream(model, 1.0);
    double sum = 0;
    g_allocations = 0;
    g_counting = true;
    for (std::size_t i = 0; i < data.rows; ++i) {
      const auto r = data.row(i);
      sum += stream.update({static_cast<double>(i), 0.0, r[0], r[1], r[2]});
    }
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << to_string(method);
    EXPECT_TRUE(std::isfinite(sum));
  }
}

}  // namespace
}  // namespace fogdrift
