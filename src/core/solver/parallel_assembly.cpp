#include "parallel_assembly.hpp"

#include <time.h>

#include <algorithm>
#include <limits>
#include <thread>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
// Serial assemblies of less CPU time than this stay on one thread: waking a sleeping helper costs the caller a
// system call (a few us) and the helper tens of microseconds before it claims anything, and each claim is an atomic
// operation shared between cores. An estimate: on the shared machine the break-even could not be resolved
// (bench/README.md, "Element evaluation on two threads, a persistent pool").
constexpr double kBreakEvenSeconds = 30.0e-6;
// Helpers evaluate at most this share of the local entries (from the back): bounds the blocks kept per element.
constexpr double kBufferedShare = 0.75;
// Blocks of each element start on a 64-byte line, so that two threads never write one line.
constexpr size_t kLineDoubles = 8;

size_t BlockSize(const Element& element) {
  const size_t m = element.num_local();
  return (2 * m + m * m + kLineDoubles - 1) / kLineDoubles * kLineDoubles;
}
}  // namespace

void EvaluateElement(const Element& element, const StepContext& ctx, bool with_tangent, const ElementBlocks& blocks) {
  const int m = element.num_local();
  Eigen::Map<Eigen::VectorXd> r(blocks.r, m), magnitude(blocks.magnitude, m);
  r.setZero();
  magnitude.setZero();
  if (!with_tangent) {
    element.AddResidualAndTangent(ctx, r, magnitude, nullptr);
    return;
  }
  Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>> J_map(blocks.J, m, m, Eigen::OuterStride<>(blocks.ld));
  Eigen::Ref<Eigen::MatrixXd> J = J_map;
  J.setZero();
  element.AddResidualAndTangent(ctx, r, magnitude, &J);
  AddSchemeRateTerms(element, ctx, J);
}

double ThreadCpuSeconds() {
  timespec now;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1.0e-9 * static_cast<double>(now.tv_nsec);
}

ParallelAssembly::ParallelAssembly(const std::vector<std::unique_ptr<Element>>& elements, int threads)
    : elements_(elements), threads_(threads) {
  FLEXMBD_DEMAND(threads >= 2 && elements.size() < std::numeric_limits<uint32_t>::max());
  const int n = static_cast<int>(elements.size());
  size_t total = 0;
  for (const auto& element : elements) total += BlockSize(*element);
  size_t buffered = 0;
  first_buffered_ = n;
  while (first_buffered_ > 0 && buffered + BlockSize(*elements[first_buffered_ - 1]) <= kBufferedShare * total) {
    buffered += BlockSize(*elements[--first_buffered_]);
  }
  for (int e = first_buffered_; e < n; ++e) {
    offsets_.push_back(buffer_.size());
    buffer_.resize(buffer_.size() + BlockSize(*elements[e]));
  }
  ready_ = std::make_unique<std::atomic<int>[]>(n - first_buffered_);
  for (int k = 0; k < n - first_buffered_; ++k) ready_[k].store(0);
  serial_fastest_[0] = serial_fastest_[1] = std::numeric_limits<double>::infinity();
}

ParallelAssembly::~ParallelAssembly() = default;

bool ParallelAssembly::Pays(bool with_tangent) const {
  return !Calibrating(with_tangent) && serial_fastest_[with_tangent] >= kBreakEvenSeconds;
}

void ParallelAssembly::RecordSerial(bool with_tangent, double seconds) {
  ++serial_count_[with_tangent];
  serial_fastest_[with_tangent] = std::min(serial_fastest_[with_tangent], seconds);
}

int ParallelAssembly::ClaimFront() {
  uint64_t claims = claims_.load(std::memory_order_relaxed);
  for (;;) {
    const uint32_t front = claims >> 32, back = static_cast<uint32_t>(claims);
    if (front >= back) return -1;
    if (claims_.compare_exchange_weak(claims, Claims(front + 1, back), std::memory_order_acq_rel,
                                      std::memory_order_relaxed)) {
      return static_cast<int>(front);
    }
  }
}

int ParallelAssembly::ClaimBack() {
  uint64_t claims = claims_.load(std::memory_order_relaxed);
  for (;;) {
    const uint32_t front = claims >> 32, back = static_cast<uint32_t>(claims);
    if (back <= front || back <= static_cast<uint32_t>(first_buffered_)) return -1;
    if (claims_.compare_exchange_weak(claims, Claims(front, back - 1), std::memory_order_acq_rel,
                                      std::memory_order_relaxed)) {
      return static_cast<int>(back - 1);
    }
  }
}

ElementBlocks ParallelAssembly::BufferOf(int element) {
  double* blocks = buffer_.data() + offsets_[element - first_buffered_];
  const int m = elements_[element]->num_local();
  return ElementBlocks{blocks, blocks + m, blocks + 2 * m, m};
}

void ParallelAssembly::HelperTask() {
  int element;
  // ctx_ and with_tangent_ are read only under a claim, which the caller waits for before it changes them.
  while ((element = ClaimBack()) >= 0) {
    EvaluateElement(*elements_[element], *ctx_, with_tangent_, BufferOf(element));
    ready_[element - first_buffered_].store(1, std::memory_order_release);
  }
}

void ParallelAssembly::Start(const StepContext& ctx, bool with_tangent) {
  if (!helpers_) helpers_ = std::make_unique<HelperThreads>(threads_ - 1, [this] { HelperTask(); });
  ctx_ = &ctx;
  with_tangent_ = with_tangent;
  claims_.store(Claims(0, static_cast<uint32_t>(elements_.size())), std::memory_order_release);
  helpers_->Wake();
}

void ParallelAssembly::WaitUntilReady(int element) {
  // At most one element's evaluation, unless the helper was descheduled: then give it the core.
  for (int spins = 0; ready_[element - first_buffered_].load(std::memory_order_acquire) == 0; ++spins) {
    if (spins > 1000) std::this_thread::yield();
  }
}

}  // namespace flexmbd
