#pragma once
// The elements of one assembly evaluated on several threads, their blocks handed to the caller in element order
// (docs/theory.md, "Assembly on several threads"). The calling thread claims elements from the front, evaluates
// each into its own scratch blocks and hands it over at once; the helpers claim from the back and evaluate into
// blocks kept per element. Where the claims meet, the caller hands over the helpers' blocks in ascending order.
// Every sum of the assembly is thus made in element order whatever thread evaluated which element, and the
// results are those of one thread bit for bit. Claims are dynamic, so a helper that wakes late or is descheduled
// takes less work and never holds up the caller by more than one element.

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "flexmbd/elements/element.hpp"
#include "helper_threads.hpp"

namespace flexmbd {

/// One element's local residual, row magnitudes and tangent (column-major, leading dimension `ld`) as evaluated.
struct ElementBlocks {
  double* r;
  double* magnitude;
  double* J;
  int ld;
};

/// Zeroes the blocks and fills them with the element's residual, magnitudes and, if asked, its whole tangent
/// (AddResidualAndTangent and AddSchemeRateTerms).
void EvaluateElement(const Element& element, const StepContext& ctx, bool with_tangent, const ElementBlocks& blocks);

/// CPU time of the calling thread [s].
double ThreadCpuSeconds();

class ParallelAssembly {
 public:
  /// For the model's elements, with `threads` >= 2 (the caller and threads - 1 helpers, started when first needed).
  ParallelAssembly(const std::vector<std::unique_ptr<Element>>& elements, int threads);
  ~ParallelAssembly();

  /// Whether assemblies of this kind go to the threads: after kCalibration serial ones have been timed
  /// (RecordSerial), when the fastest of them took at least the break-even time.
  bool Pays(bool with_tangent) const;
  /// True until kCalibration serial assemblies of this kind have been timed.
  bool Calibrating(bool with_tangent) const { return serial_count_[with_tangent] < kCalibration; }
  /// The CPU time of a serial assembly of this kind (ThreadCpuSeconds, which the machine's load does not
  /// lengthen, unlike a wall-clock time) [s].
  void RecordSerial(bool with_tangent, double seconds);

  /// Evaluates every element for ctx and calls hand_over(element index, its blocks) on the calling thread, once
  /// per element in ascending order. `scratch` holds the caller's blocks for the largest element. Allocates
  /// nothing but on its first call (the helpers' start).
  template <class HandOver>
  void Evaluate(const StepContext& ctx, bool with_tangent, const ElementBlocks& scratch, HandOver&& hand_over);

 private:
  static constexpr int kCalibration = 3;
  static uint64_t Claims(uint32_t front, uint32_t back) { return (uint64_t{front} << 32) | back; }
  /// The next element from the front, or -1 when the claims have met.
  int ClaimFront();
  /// The next element from the back (not below first_buffered_), or -1.
  int ClaimBack();
  void HelperTask();
  ElementBlocks BufferOf(int element);
  /// Publishes a new assembly to the helpers (starting them on the first).
  void Start(const StepContext& ctx, bool with_tangent);
  /// Waits until the helper evaluating `element` has filled its blocks.
  void WaitUntilReady(int element);

  const std::vector<std::unique_ptr<Element>>& elements_;
  const int threads_;
  int first_buffered_;                ///< helpers claim only elements from here on (bounds the buffer's size)
  std::vector<size_t> offsets_;       ///< per buffered element: start of its blocks in buffer_
  std::vector<double> buffer_;
  std::unique_ptr<std::atomic<int>[]> ready_;  ///< per buffered element: 1 once a helper has filled its blocks
  std::atomic<uint64_t> claims_{0};   ///< front (high 32 bits) and back (low 32): [front, back) is unclaimed
  const StepContext* ctx_ = nullptr;  ///< the assembly in progress, written before claims_ publishes it
  bool with_tangent_ = false;
  double serial_fastest_[2];
  int serial_count_[2] = {0, 0};
  std::unique_ptr<HelperThreads> helpers_;
};

template <class HandOver>
void ParallelAssembly::Evaluate(const StepContext& ctx, bool with_tangent, const ElementBlocks& scratch,
                                HandOver&& hand_over) {
  Start(ctx, with_tangent);
  int element;
  while ((element = ClaimFront()) >= 0) {
    EvaluateElement(*elements_[element], ctx, with_tangent, scratch);
    hand_over(element, scratch);
  }
  const int met = static_cast<int>(claims_.load() >> 32);
  for (element = met; element < static_cast<int>(elements_.size()); ++element) {
    WaitUntilReady(element);
    hand_over(element, BufferOf(element));
    ready_[element - first_buffered_].store(0, std::memory_order_relaxed);
  }
}

}  // namespace flexmbd
