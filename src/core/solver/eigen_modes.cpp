// From eigenvalues and vectors to reported modes (docs/theory.md, eq. (E5)): conjugate pairs, rigid-body
// modes, normalisation and order.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "dense_decompositions.hpp"
#include "eigen_internal.hpp"

namespace flexmbd {
namespace eigen_internal {
namespace {
// Rigid-body roots come out of the arithmetic at four kinds of round-off level (theory (E5)):
// - the eigensolver's, ~1e-12 of the frequency scale with the shifted inverse, up to ~sqrt(eps) of it from the
//   round-off of the reduced matrices (the dense solvers: rigid_tolerance), a fraction of its shift (the sparse
//   method): the solver's limit;
// - the round-off of the stiffness terms the shape engages, x^H K x ~ 1e-17 |x|^T |K| |x| (a free beam, whose
//   rigid motions cancel large element terms): below kCancellation. Elastic modes of stiff finite-element
//   models cancel too, but far less (1e-10 for a 40-element Timoshenko beam with GA L^2 / EI = 1e6);
// - a shape that engages nothing but round-off, |x|^T |K| |x| / x^H M x below kIdle scale^2 (a free joint
//   between loaded bodies, whose root is the round-off of the reduced matrices, ~1e-16 scale^2).
// Only roots below kResolved of the scale are candidates for the last two, and both weigh the rows of the node and
// joint unknowns only. Element states' rows are first order and have no inertia of their own: over them x^H M x is
// the cross term x_states^H M_xq x_kinematic, ~|x_kinematic| |x_states|, and |x|^T |K| |x| holds their own
// stiffness, ~|x_states|^2, so a shape that moved mostly states passed the cancellation test (the Goland wing's
// inflow roots: 46 of them at 10 m/s; at 50 m/s one on one machine, none on another). Over the kinematic rows a
// root of the states' own equations shows the motion it drives, or round-off, against the stiffness that engages:
// s^2 x^H M x / terms >= 3e-10 and terms / (scale^2 x^H M x) >= 1e-3 for the Goland wing's clamped root strip at
// 50 m/s, against 1e-14 for both.
constexpr double kCancellation = 1.0e-14, kIdle = 1.0e-14, kResolved = 1.0e-4;
// - the reference's: a moving reference is known only to the round-off of (E2)'s second differences, ~1e-9 of its
//   curvature terms (a free hub at 10 rad/s, EigenRoundOff.RotationOfAFreeHubIsARigidBodyModeNotADivergence: its
//   accelerations and multipliers 4.5e-10 off). The stiffness they feed is ~(mass) rate^2, so a root's s^2 is
//   uncertain by ~1e-9 rate^2 per unit mass, and |s| below sqrt(1e-9) = 3e-5 of the rate is not told from zero
//   (measured there: the hub's rotation at 1.9e-5 of the rate, a real pair of roots). Below kReferenceResolution
//   of the rate (ReferenceRate) a root is rigid.
constexpr double kReferenceResolution = 1.0e-4;
// A mode's growth_round_off is this many times its root's round-off: the solvers' estimates are first-order ones
// (a condition number times a backward error). An undamped root comes out with Re s of either sign: ~eps w for a
// well-conditioned root (w the frequency scale; 2e-11 of |s| for the lowest modes of the rotating cantilever,
// w ~ 5e4 rad/s, |s| ~ 4 rad/s), ~sqrt(eps) w for a double root split by round-off (the free translations of a body
// spinning at 2 rad/s, seen from it: growth 2.7e-8 1/s, estimated round-off 1.3e-7 1/s).
constexpr double kRoundOffMargin = 10.0;

}  // namespace

bool IsRigidRoot(const LinearisedSystem& system, const RawMode& mode, int num_states, double scale, double limit) {
  const double s = std::abs(mode.s);
  if (s <= limit) return true;
  if (s > kResolved * scale) return false;
  const Eigen::Index kinematic = mode.x.size() - num_states;
  const Eigen::VectorXd magnitude = mode.x.cwiseAbs(), re = mode.x.real(), im = mode.x.imag();
  const Eigen::VectorXd re_rows = system.M * re, im_rows = system.M * im;
  const double inertia =
      re.head(kinematic).dot(re_rows.head(kinematic)) + im.head(kinematic).dot(im_rows.head(kinematic));
  if (!(inertia > 0)) return false;
  const Eigen::VectorXd stiffness = system.K.cwiseAbs() * magnitude, damping = system.D.cwiseAbs() * magnitude;
  const double terms = magnitude.head(kinematic).dot(stiffness.head(kinematic)) +
                       s * magnitude.head(kinematic).dot(damping.head(kinematic));
  return s * s * inertia <= kCancellation * terms || terms <= kIdle * scale * scale * inertia;
}

namespace {

// The shape over the kinematic unknowns (x = T y), scaled so that its largest component is 1.
Eigen::VectorXcd Normalised(const LinearisedSystem& system, const Eigen::VectorXcd& y) {
  const Eigen::VectorXd re = system.T * y.real(), im = system.T * y.imag();
  const Eigen::VectorXcd x =
      re.cast<std::complex<double>>() + std::complex<double>(0, 1) * im.cast<std::complex<double>>();
  Eigen::Index k = 0;
  if (x.size() == 0 || x.cwiseAbs().maxCoeff(&k) == 0.0) return x;
  return x / x[k];
}

}  // namespace

void ClassifyModes(const Model& model, const LinearisedSystem& system, const std::vector<RawMode>& all, bool symmetric,
                   int num_states, double scale, double limit, const EigenOptions& options, EigenResult* result) {
  const double resolved = std::max(limit, kReferenceResolution * ReferenceRate(model, system.reference));
  std::vector<const RawMode*> rigid;
  std::vector<Mode> modes;
  for (const RawMode& raw : all) {
    if (IsRigidRoot(system, raw, num_states, scale, resolved)) {
      rigid.push_back(&raw);
      continue;
    }
    if (raw.s.imag() < 0) continue;  // the conjugate of a root with Im s > 0
    Mode mode;
    mode.eigenvalue = raw.s;
    const double magnitude = std::abs(raw.s);
    mode.frequency_hz = magnitude / (2 * M_PI);
    mode.damped_frequency_hz = std::abs(raw.s.imag()) / (2 * M_PI);
    mode.damping_ratio = -raw.s.real() / magnitude + 0.0;  // + 0.0: no negative zero in tables
    mode.growth_round_off = kRoundOffMargin * raw.round_off;
    mode.shape = Normalised(system, raw.x);
    modes.push_back(std::move(mode));
  }
  if (!rigid.empty()) {
    // Shapes of the rigid-body modes: the leading directions spanned by the zero roots' vectors.
    const int count = static_cast<int>(rigid.size());
    const int num_rigid = symmetric ? count : (count + 1) / 2;
    Eigen::MatrixXd vectors(rigid.front()->x.size(), 2 * count);
    for (int i = 0; i < count; ++i) {
      vectors.col(2 * i) = rigid[i]->x.real();
      vectors.col(2 * i + 1) = rigid[i]->x.imag();
    }
    const Eigen::MatrixXd U = dense::LeftSingularBasis(vectors).vectors;
    for (int i = 0; i < num_rigid; ++i) {
      Mode mode;
      mode.eigenvalue = 0.0;
      mode.rigid_body = true;
      mode.shape = Normalised(system, U.col(i).cast<std::complex<double>>());
      modes.push_back(std::move(mode));
    }
  }
  std::stable_sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) {
    if (a.rigid_body != b.rigid_body) return a.rigid_body;
    return a.frequency_hz < b.frequency_hz;
  });
  result->frequency_scale_hz = scale / (2 * M_PI);
  result->num_rigid_body =
      static_cast<int>(std::count_if(modes.begin(), modes.end(), [](const Mode& m) { return m.rigid_body; }));
  if (options.num_modes > 0 && static_cast<int>(modes.size()) > options.num_modes) modes.resize(options.num_modes);
  result->modes = std::move(modes);
}

}  // namespace eigen_internal
}  // namespace flexmbd
