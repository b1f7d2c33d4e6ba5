// The three-degree-of-freedom typical section of Conner, Tang, Dowell and Virgin (J. Fluids Struct. 11, 1997)
// from its own files (config/conner_section/): structural frequencies, linear flutter speed, and the free motion
// just below and above flutter against the eigen-analysis (docs/validation.md).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/cycle_statistics.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "../integration/helpers/csv_table.hpp"
#include "peak_rate.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace conner_section_test {

using test::Replaced;

const std::string kDir = std::string(FLEXMBD_SOURCE_DIR) + "/config/conner_section/";

ModelSpec Case(const std::string& yaml) { return LoadModelSpec(kDir + "conner_section.urdf", kDir + yaml); }

// The text of one of the case's YAML files.
std::string CaseText(const std::string& yaml) { return test::ReadFile(kDir + yaml); }

// Largest real part of the roots at speed U with N inflow states [1/s] (> 0: unstable).
double LeastStableRoot(double U, int states) {
  ModelSpec spec = Case("flutter_eigen.yaml");
  spec.aero_sections.at(0).velocity = U;
  spec.aero_sections.at(0).inflow_states = states;
  const Model model = BuildModel(spec);
  const EigenResult result = EigenAnalysis(model, model.initial_state(), EigenOptions{});
  double worst = -1e300;
  for (const Mode& mode : result.modes) worst = std::max(worst, mode.eigenvalue.real());
  return worst;
}

TEST(ConnerSection, StructuralFrequenciesMatchPublished) {
  // flexmbd_run on the case's own files.
  const std::string yaml = CaseText("structure_modes.yaml");
  const std::string table = test::RunnerOutput("config/conner_section/conner_section.urdf", yaml, "conner_modes");
  // Published 4.443, 9.221 and 19.433 Hz, given to four figures and measured on the rig: 0.2% covers both
  // the rounding of the paper's data and of its frequencies.
  constexpr double kPublished[3] = {4.443, 9.221, 19.433};
  constexpr double kRelative = 2.0e-3;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(test::TableFrequency(table, k + 1), kPublished[k], kRelative * kPublished[k]) << table;
  }
  EXPECT_TRUE(std::isnan(test::TableFrequency(table, 4))) << table;
}

// The flutter speed the runner prints for flutter_sweep.yaml with `states` inflow states [m/s] (NaN if none), and
// the runner's output.
struct RunnerFlutter {
  double speed = NAN, frequency_hz = NAN;
  int mode = 0;
  std::string output;
};

RunnerFlutter RunnerFlutterSpeed(const std::string& yaml, const std::string& name) {
  RunnerFlutter flutter;
  flutter.output = test::RunnerOutput("config/conner_section/conner_section.urdf", yaml, name);
  const std::string prefix = "flexmbd_run: flutter: mode ";
  const size_t line = flutter.output.find(prefix);
  if (line != std::string::npos) {
    std::sscanf(flutter.output.c_str() + line + prefix.size(), "%d at U = %lf m/s (%lf Hz)", &flutter.mode,
                &flutter.speed, &flutter.frequency_hz);
  }
  return flutter;
}

RunnerFlutter RunnerFlutterSpeed(int states) {
  const std::string yaml = Replaced(CaseText("flutter_sweep.yaml"), "inflow_states: 4",
                                    "inflow_states: " + std::to_string(states));
  return RunnerFlutterSpeed(yaml, "conner_flutter_" + std::to_string(states));
}

// The runner bisects the sweep's change of stability to a bracket of 0.01% of the speed; its printed speed (6
// digits) must be within the 0.1% the issue asks of the speed this test's own bisection on the sign of the least
// stable root found to 0.01% before the runner did it (23.954 m/s with four states, 18.475 m/s quasi-steady).
TEST(ConnerSection, RunnerLocatesTheFlutterSpeed) {
  constexpr double kRelative = 1.0e-3;
  const RunnerFlutter four = RunnerFlutterSpeed(4);
  EXPECT_NEAR(four.speed, 23.954, kRelative * 23.954) << four.output;
  // The pitch-flap mode, between the pitch (9.2 Hz) and plunge (4.4 Hz) frequencies of the structure.
  EXPECT_GT(four.frequency_hz, 4.443) << four.output;
  EXPECT_LT(four.frequency_hz, 9.221) << four.output;
  const RunnerFlutter quasi_steady = RunnerFlutterSpeed(0);
  EXPECT_NEAR(quasi_steady.speed, 18.475, kRelative * 18.475) << quasi_steady.output;
}

// The same sweep about the static aeroelastic equilibrium under gravity: the section sags and pitches nose up by
// S_alpha g / K_alpha = 1.3 deg, which changes the linearised equations only through the rigid kinematics (the
// gravity stiffness S_alpha g sin(alpha) ~ 5e-4 K_alpha, the plunge-pitch coupling S_alpha cos(alpha) by 3e-4),
// so the flutter speed moves by that order (measured 0.04%): within 0.1% of the unloaded one.
TEST(ConnerSection, FlutterSpeedAboutTheStaticAeroelasticEquilibrium) {
  std::string yaml = Replaced(CaseText("flutter_sweep.yaml"), "gravity: [0.0, 0.0, 0.0]", "gravity: [0.0, 0.0, -9.81]");
  yaml = Replaced(yaml, "modes: 0", "modes: 0\n    static_first: true");
  const RunnerFlutter loaded = RunnerFlutterSpeed(yaml, "conner_flutter_static");
  EXPECT_NE(loaded.output.find("about the static aeroelastic equilibrium"), std::string::npos) << loaded.output;
  const double unloaded = RunnerFlutterSpeed(4).speed;
  EXPECT_NE(loaded.speed, unloaded) << loaded.output;  // linearised about another state
  EXPECT_NEAR(loaded.speed, unloaded, 1.0e-3 * unloaded) << loaded.output;
}

TEST(ConnerSection, RunnerSaysWhenNoModeChangesStability) {
  const std::string below = Replaced(CaseText("flutter_sweep.yaml"), "22, 24, 26, 28, 30]", "22]");
  const RunnerFlutter none = RunnerFlutterSpeed(below, "conner_no_flutter");
  EXPECT_TRUE(std::isnan(none.speed)) << none.output;
  EXPECT_NE(none.output.find("flexmbd_run: flutter: no mode changes stability between 2 and 22 m/s"),
            std::string::npos)
      << none.output;
}

// The fan-plot table as CSV (output.csv): one row per speed, frequencies and damping ratios of the six modes (three
// structural, the inflow states' real roots and their damped pair); the flutter mode's damping ratio changes sign
// between 22 and 24 m/s.
TEST(ConnerSection, AirspeedSweepTableGoesToTheCsv) {
  const std::string csv = testing::TempDir() + "conner_fan.csv";
  const RunnerFlutter flutter =
      RunnerFlutterSpeed(CaseText("flutter_sweep.yaml") + "output: {csv: " + csv + "}\n", "conner_fan_csv");
  const test::CsvTable table = test::ReadCsv(csv);
  EXPECT_EQ(table.header, std::vector<std::string>({"airspeed", "f1_Hz", "f2_Hz", "f3_Hz", "f4_Hz", "f5_Hz", "f6_Hz",
                                                    "zeta1", "zeta2", "zeta3", "zeta4", "zeta5", "zeta6"}))
      << flutter.output;
  ASSERT_EQ(table.rows.size(), 15u);
  EXPECT_EQ(table.rows.front()[0], 2.0);
  EXPECT_EQ(table.rows.back()[0], 30.0);
  const size_t zeta = table.Column("zeta" + std::to_string(flutter.mode));
  EXPECT_GT(table.rows[10][zeta], 0.0);  // 22 m/s
  EXPECT_LT(table.rows[11][zeta], 0.0);  // 24 m/s
}

// output.cycle_from on a motion that has decayed to rest: 22 m/s, below flutter, released with 1 deg of pitch; its
// least damped root decays at about 1.5/s, so by 14 s the pitch is below 1e-8 rad, under the step error test's
// floor (1e-7 rad by default), and the runner says there is no cycle instead of a frequency of noise.
TEST(ConnerSection, RunnerReportsNoCycleAtRest) {
  std::string yaml = Replaced(CaseText("flutter_below.yaml"), "t_end: 4.0", "t_end: 18.0");
  yaml = Replaced(yaml, "output: {rate_hz: 200}", "output: {rate_hz: 200, cycle_from: 14.0}");
  const std::string out = test::RunnerOutput("config/conner_section/conner_section.urdf", yaml, "conner_rest");
  for (const std::string variable : {"plunge", "pitch", "flap_hinge"}) {
    EXPECT_NE(out.find("flexmbd_run: cycle of " + variable + " over [14, 18] s: none, at rest at "), std::string::npos)
        << out;
  }
  EXPECT_EQ(out.find("Hz"), std::string::npos) << out;
}

// Aero outputs in the CSV: at the static aeroelastic equilibrium (the run's first sample) the flow is steady, the
// inflow states are zero and the lift is the steady thin-airfoil lift 2 pi q (2b) span (alpha + T10 delta / pi),
// T10 = sqrt(1 - c^2) + acos(c) (Theodorsen's flap term; REFERENCES section 5.3). The pitch spring rests at 3 deg.
TEST(ConnerSection, CsvCarriesTheSteadySectionLoads) {
  const std::string csv = testing::TempDir() + "conner_steady.csv";
  std::string yaml =
      Replaced(CaseText("flutter_below.yaml"), "pitch: {spring: {k: 37.34}, initial: {position_deg: 1.0}}",
               "pitch: {spring: {k: 37.34, rest_deg: 3.0}}");
  yaml = Replaced(yaml, "t_end: 4.0", "t_end: 0.01\n  static_first: true");
  yaml = Replaced(yaml, "output: {rate_hz: 200}", "output: {rate_hz: 200, csv: " + csv + "}");
  const std::string out = test::RunnerOutput("config/conner_section/conner_section.urdf", yaml, "conner_steady");
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_FALSE(table.rows.empty()) << out;
  const std::vector<double>& first = table.rows.front();
  for (const std::string name : {"aero.conner.lift", "aero.conner.moment", "aero.conner.hinge_moment"}) {
    EXPECT_NE(std::find(table.header.begin(), table.header.end(), name), table.header.end()) << name << "\n" << out;
  }
  for (int k = 1; k <= 6; ++k) EXPECT_EQ(first.at(table.Column("aero.conner.mu_" + std::to_string(k))), 0.0) << k;
  const double alpha = first.at(table.Column("joint.pitch.position"));
  const double delta = first.at(table.Column("joint.flap_hinge.position"));
  const double computed = first.at(table.Column("aero.conner.lift"));
  const double rho = 1.225, U = 22.0, b = 0.127, c = 0.5;
  const double t10 = std::sqrt(1 - c * c) + std::acos(c);
  const double lift = 2 * M_PI * 0.5 * rho * U * U * 2 * b * (alpha + t10 / M_PI * delta);
  std::printf("alpha %.6f rad, delta %.6f rad: lift %.6f N (steady thin airfoil %.6f N)\n", alpha, delta, computed,
              lift);
  EXPECT_GT(alpha, 0.01);
  // The lift is evaluated at the sample's own alpha and delta, so the closed form holds to the flap series' cut
  // (6e-8 relative, docs/theory.md (A4)) and round-off, whatever the static solution's tolerance.
  constexpr double kRelative = 1.0e-6;
  EXPECT_NEAR(computed, lift, kRelative * lift);
  // At the equilibrium each load holds its spring: lift K_h h (h = plunge up), moment K_alpha (alpha - 3 deg),
  // hinge moment K_beta delta; to the static solution's Newton tolerance (1e-6 relative; measured 4e-15).
  const double moment = first.at(table.Column("aero.conner.moment"));
  const double hinge = first.at(table.Column("aero.conner.hinge_moment"));
  EXPECT_NEAR(computed, 2818.8 * first.at(table.Column("joint.plunge.position")), kRelative * lift);
  EXPECT_NEAR(moment, 37.34 * (alpha - 3.0 * M_PI / 180), kRelative * std::abs(moment));
  EXPECT_NEAR(hinge, 3.9 * delta, kRelative * std::abs(hinge));
}

TEST(ConnerSection, FlutterSpeedMatchesConnersTheory) {
  // Conner's theory gives about 23.9 m/s (the rig 24.3): with four or more inflow states the finite-state model
  // is within 2% of it (its C(k) within 1% at the flutter reduced frequency k = w b / U ~ 0.2, plus the
  // rounding of the section's data).
  constexpr double kTheory = 23.9, kRelative = 0.02;
  for (int states : {4, 6, 8}) {
    const RunnerFlutter flutter = RunnerFlutterSpeed(states);
    std::printf("N = %d: flutter at %.4f m/s, %.3f Hz\n", states, flutter.speed, flutter.frequency_hz);
    EXPECT_NEAR(flutter.speed, kTheory, kRelative * kTheory) << flutter.output;
  }
  // Quasi-steady (no wake lag) flutters much earlier: the lag of the circulatory lift stabilises this section.
  const RunnerFlutter quasi_steady = RunnerFlutterSpeed(0);
  std::printf("quasi-steady: flutter at %.4f m/s, %.3f Hz\n", quasi_steady.speed, quasi_steady.frequency_hz);
  EXPECT_LT(quasi_steady.speed, (1 - kRelative) * kTheory) << quasi_steady.output;
}

struct FreeMotion {
  double rate = 0;           // of the pitch peaks [1/s]
  double eigen_rate = 0;     // real part of the least stable root at the same speed [1/s]
  double books = 0;          // largest |E - E0 + numerical - external| [J]
  double throughput = 0;     // largest |external work| [J]
};

FreeMotion FreeRun(const std::string& yaml, double t0, double t1) {
  const ModelSpec spec = Case(yaml);
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  const int pitch = model.FindVariable("pitch");
  std::vector<double> t, x;
  FreeMotion run;
  double e0 = NAN;
  simulation.Run([&](const OutputSample& s) {
    t.push_back(s.t);
    x.push_back(s.position[pitch]);
    if (std::isnan(e0)) e0 = s.total();
    run.books =
        std::max(run.books, std::abs(s.total() - e0 + s.numerical_dissipation + s.dissipated - s.external_work));
    run.throughput = std::max(run.throughput, std::abs(s.external_work));
  });
  run.rate = test::PeakRate(t, x, t0, t1);
  run.eigen_rate = LeastStableRoot(spec.aero_sections.at(0).velocity, spec.aero_sections.at(0).inflow_states);
  return run;
}

TEST(ConnerSection, FreeDecayBelowFlutterMatchesEigenDamping) {
  // From 1 s on the other modes have decayed (their rates are several times faster): the peaks follow the least
  // damped mode. The peaks of a sampled sine are off by up to (w dt)^2 / 8 relative, which shifts the fitted rate
  // by far less than 2%; default error_tol 1e-4 per step. Fitted up to 2.5 s: later the pitch is below 1e-4 rad,
  // the steps grow against the error test's absolute floor (1e-7 rad) and the 200 Hz samples, interpolated within
  // them, flatten the peaks (the fit over [1, 4] s gave 1.49/s).
  const FreeMotion run = FreeRun("flutter_below.yaml", 1.0, 2.5);
  std::printf("22 m/s: decay %.4f 1/s, eigen %.4f 1/s; books %.3g J of %.3g J\n", -run.rate, -run.eigen_rate, run.books,
              run.throughput);
  ASSERT_LT(run.eigen_rate, 0.0);
  constexpr double kRelative = 0.02;
  EXPECT_NEAR(run.rate, run.eigen_rate, kRelative * std::abs(run.eigen_rate));
  // Energy books: kinetic + potential + numerical dissipation - air's work stays at its start value; the
  // local error of the steps (1e-4 relative per step) bounds what is left, against the energy that flowed.
  constexpr double kBooks = 1.0e-2;
  EXPECT_LT(run.books, kBooks * run.throughput);
}

TEST(ConnerSection, MotionAboveFlutterGrows) {
  // 1.2 s: the motion grows from 1 deg to about 10 deg, where the linear roots still hold; fitted from 0.4 s, when
  // the other modes have decayed.
  const FreeMotion run = FreeRun("flutter_above.yaml", 0.4, 1.2);
  std::printf("26 m/s: growth %.4f 1/s, eigen %.4f 1/s\n", run.rate, run.eigen_rate);
  ASSERT_GT(run.eigen_rate, 0.0);
  constexpr double kRelative = 0.02;
  EXPECT_NEAR(run.rate, run.eigen_rate, kRelative * run.eigen_rate);
}

// The freeplay runs below are judged from kSettled on: from the start's flap rate of 2 rad/s the doubled gap's flap
// grows inside its gap and first reaches a stop at 19.1 s, the given and halved gaps' within a second.
constexpr double kSettled = 20.0;

double Median(std::vector<double> values) {
  if (values.empty()) return NAN;
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(middle), values.end());
  return values[middle];
}

// The settled motion with flap freeplay (freeplay_lco.yaml, gap scaled) from kSettled on, over its first kContacts
// contacts. The cycle is irregular, and now and then the flap stays inside its gap (its free root grows at only
// 0.040 1/s): for 16 to 47 s at a time in runs to 150 s, and when it falls in is decided by the last bits of the
// arithmetic (glibc's FMA variants of libm moved it, docs/validation.md). Statistics of a fixed interval (RMS,
// spectrum, a contact count) then depend on whether it holds such an episode. So the run goes on until kContacts
// contacts are in, the amplitude is taken at the contacts, and the plunge over the windows in which the flap strikes
// both stops.
constexpr int kContacts = 300;
// Room for kContacts (about 30 s of striking, 10 contacts a second) after two of the longest stays measured.
constexpr double kLongestRun = 150.0;

struct LimitCycle {
  double gap = 0;            // [rad]
  double flap_peak = 0;      // median over the contacts of the largest |flap angle| in each, over the gap
  double flap_peak_first_half = 0, flap_peak_second_half = 0;  // the same over each half of the contacts
  int contacts = 0;          // that the medians are taken over
  double plunge = 0;         // median over the 1 s windows in which the flap strikes both stops of the plunge's RMS [m]
  CycleStatistics flap;      // over the windows in which the flap strikes both stops (frequency, RMS)
  double books = 0, throughput = 0;  // as FreeMotion [J]
};

// The largest |x| of a contact whose largest sample is x[k], from the parabola through x[k - 1], x[k], x[k + 1]:
// the contact lasts about 8 samples (half a period of the flap on the stop's 2.03 N m/rad), so a sample may miss
// its peak by 2% while the parabola's error is of the fourth order in the sample interval.
double InterpolatedPeak(const std::vector<double>& x, size_t k) {
  const double a = std::abs(x[k - 1]), b = std::abs(x[k]), c = std::abs(x[k + 1]);
  const double curvature = a - 2 * b + c;
  return curvature < 0 ? b - (a - c) * (a - c) / (8 * curvature) : b;
}

// Per sample of x the stops in contact (bit 0: lower, bit 1: upper): the peaks |x| (InterpolatedPeak) of the
// contacts that begin and end inside the samples, in order.
std::vector<double> ContactPeaks(const std::vector<double>& x, const std::vector<int>& contact) {
  const size_t first = 0, last = x.size();
  std::vector<double> peaks;
  size_t k = first;
  while (k < last) {
    if (contact[k] == 0) {
      ++k;
      continue;
    }
    size_t end = k, largest = k;
    for (; end < last && contact[end] != 0; ++end) {
      if (std::abs(x[end]) > std::abs(x[largest])) largest = end;
    }
    if (k > first && end < last) peaks.push_back(InterpolatedPeak(x, largest));
    k = end;
  }
  return peaks;
}

LimitCycle FreeplayRun(double gap_scale) {
  ModelSpec spec = Case("freeplay_lco.yaml");
  const auto hinge = std::find_if(spec.joints.begin(), spec.joints.end(),
                                  [](const JointSpec& joint) { return joint.name == "flap_hinge"; });
  for (StopSpec& stop : hinge->effects.at(0).stops) stop.limit *= gap_scale;
  spec.solver.t_end = kLongestRun;  // stopped once kContacts contacts are in
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  const int flap = model.FindVariable("flap_hinge"), plunge = model.FindVariable("plunge");
  EXPECT_EQ(model.stops().size(), 2u);  // the hinge's lower and upper stops, bits 0 and 1 below
  std::vector<double> x, h;
  std::vector<int> contact;
  LimitCycle cycle;
  cycle.gap = 2.12 * M_PI / 180 * gap_scale;
  double e0 = NAN;
  int begun = 0;  // contacts begun from kSettled on; one more than kContacts, for the last to end
  simulation.StopWhen([&] { return begun > kContacts + 1; });
  simulation.Run([&](const OutputSample& s) {
    if (s.t >= kSettled) {
      const int touching = (s.stops.at(0).in_contact ? 1 : 0) | (s.stops.at(1).in_contact ? 2 : 0);
      if (touching != 0 && (contact.empty() || contact.back() == 0)) ++begun;
      x.push_back(s.position[flap]);
      h.push_back(s.position[plunge]);
      contact.push_back(touching);
    }
    if (std::isnan(e0)) e0 = s.total();
    cycle.books =
        std::max(cycle.books, std::abs(s.total() - e0 + s.numerical_dissipation + s.dissipated - s.external_work));
    cycle.throughput = std::max(cycle.throughput, std::abs(s.external_work));
  });
  const double dt = 1.0 / spec.output.rate_hz;
  std::vector<double> peaks = ContactPeaks(x, contact);
  if (peaks.size() > static_cast<size_t>(kContacts)) peaks.resize(kContacts);
  const auto middle = peaks.begin() + static_cast<long>(peaks.size() / 2);
  cycle.flap_peak = Median(peaks) / cycle.gap;
  cycle.contacts = static_cast<int>(peaks.size());
  cycle.flap_peak_first_half = Median(std::vector<double>(peaks.begin(), middle)) / cycle.gap;
  cycle.flap_peak_second_half = Median(std::vector<double>(middle, peaks.end())) / cycle.gap;
  // The flap's spectrum over the windows that strike both stops, end to end: a stay in the gap would add its own
  // slower motion (4.2 Hz instead of 4.74 Hz for a 31 s stay in 60 s).
  const size_t window = static_cast<size_t>(std::lround(spec.output.rate_hz));  // 1 s: about 5 periods
  std::vector<double> plunge_rms, striking;
  for (size_t first = 0; first + window <= h.size(); first += window) {
    int struck = 0;
    for (size_t k = first; k < first + window; ++k) struck |= contact[k];
    if (struck != 3) continue;
    const auto begin = static_cast<long>(first), end = static_cast<long>(first + window);
    plunge_rms.push_back(MeasureCycle(std::vector<double>(h.begin() + begin, h.begin() + end), dt).rms);
    striking.insert(striking.end(), x.begin() + begin, x.begin() + end);
  }
  cycle.flap = MeasureCycle(striking, dt);
  cycle.plunge = Median(plunge_rms);
  return cycle;
}

// Limit cycles with flap freeplay at 0.27 U_f (issue 17, case 1): the section with the flap free inside the gap
// is unstable at this speed and the stops bound its motion. The stops are linear and start at the gap, so the
// equations are homogeneous of degree one in (motion, gap): a cycle scaled with the gap is again a cycle, and the
// settled amplitude is proportional to the gap (from the same initial flap rate, so each run must find its cycle).
// The bounds come from 45 runs, the three gaps each started at 2 (1 + k 1e-6) rad/s, k = 0..14 (docs/validation.md):
// a start changed at round-off gives another stretch of the irregular cycle, so they measure what a window of the
// cycle leaves open, with margin.
TEST(ConnerSection, FreeplayLimitCycleAmplitudeScalesWithTheGap) {
  const LimitCycle half = FreeplayRun(0.5), given = FreeplayRun(1.0), twice = FreeplayRun(2.0);
  for (const LimitCycle* c : {&half, &given, &twice}) {
    std::printf("gap %.4f deg: flap peak %.4f of the gap (median of %d contacts; halves %.4f, %.4f), RMS %.4f of the "
                "gap, %.4f Hz; plunge %.4e m; books %.2e J of %.2e J\n",
                c->gap * 180 / M_PI, c->flap_peak, c->contacts, c->flap_peak_first_half, c->flap_peak_second_half,
                c->flap.rms / c->gap, c->flap.frequency_hz, c->plunge, c->books, c->throughput);
    // A cycle striking its stops: about 10 contacts a second (both stops in each 4.75 Hz period), so kContacts by
    // kLongestRun.
    EXPECT_EQ(c->contacts, kContacts);
    // Settled: the median peak of the first half of the contacts within 5% of the second half's (measured over 20 s
    // halves 0.980 to 1.018 over the 45 runs).
    EXPECT_NEAR(c->flap_peak_second_half / c->flap_peak_first_half, 1.0, 0.05);
    // Energy books as FreeMotion: no dissipation (restitution 1), the air's work balances the rest.
    EXPECT_LT(c->books, 1.0e-2 * c->throughput);
  }
  // Amplitude proportional to the gap. Over the 45 runs the median peak is 1.464 to 1.493 of the gap (0.48% standard
  // deviation), and the ratios below fell within 0.982 to 1.011 (0.59%): 3% is five standard deviations. The plunge,
  // not locked to the flap, wanders more from window to window: ratios 0.960 to 1.077 (2.7%), 8% three standard
  // deviations. (As this test had it, the whole RMS over [30, 60] s, the flap's ratios spread from 0.764 to 1.057
  // and the plunge's from 0.848 to 1.175, and 7 of the 15 starts failed: one 30 s window holds an episode in the
  // gap or misses it.)
  constexpr double kFlapScaling = 0.03, kPlungeScaling = 0.08;
  EXPECT_NEAR(half.flap_peak / given.flap_peak, 1.0, kFlapScaling);
  EXPECT_NEAR(twice.flap_peak / given.flap_peak, 1.0, kFlapScaling);
  EXPECT_NEAR(half.plunge * 2 / given.plunge, 1.0, kPlungeScaling);
  EXPECT_NEAR(twice.plunge / 2 / given.plunge, 1.0, kPlungeScaling);
  // The frequency does not depend on the gap: over the 45 runs 4.707 to 4.765 Hz, differences from the given gap's
  // -0.035 to +0.047 Hz (0.017 Hz standard deviation); two 1/30 Hz bins are four standard deviations.
  constexpr double kBins = 2.0 / 30.0;
  EXPECT_NEAR(half.flap.frequency_hz, given.flap.frequency_hz, kBins);
  EXPECT_NEAR(twice.flap.frequency_hz, given.flap.frequency_hz, kBins);
}

// The runner reports the cycle of every joint variable over [output.cycle_from, t_end]: the statistics of its own
// samples, which it also writes to the CSV.
TEST(ConnerSection, RunnerReportsTheFreeplayLimitCycle) {
  const std::string csv = testing::TempDir() + "conner_lco.csv";
  const std::string yaml = Replaced(CaseText("freeplay_lco.yaml"), "output: {rate_hz: 200, cycle_from: 30.0}",
                                    "output: {rate_hz: 200, cycle_from: 30.0, csv: " + csv + "}");
  const std::string out = test::RunnerOutput("config/conner_section/conner_section.urdf", yaml, "conner_lco");
  const test::CsvTable table = test::ReadCsv(csv);
  std::vector<double> flap;
  for (const std::vector<double>& row : table.rows) {
    if (row.at(0) >= 30.0) flap.push_back(row.at(table.Column("joint.flap_hinge.position")));
  }
  const CycleStatistics expected = MeasureCycle(flap, 1.0 / 200);
  const std::string prefix = "flexmbd_run: cycle of flap_hinge over [30, 60] s: ";
  const size_t line = out.find(prefix);
  ASSERT_NE(line, std::string::npos) << out;
  double mean = 0, amplitude = 0, rms = 0, frequency = 0;
  ASSERT_EQ(std::sscanf(out.c_str() + line + prefix.size(),
                        "mean %lf, amplitude %lf (half the peak-to-peak), RMS %lf, frequency %lf Hz", &mean, &amplitude,
                        &rms, &frequency),
            4)
      << out;
  EXPECT_EQ(flap.size(), 6001u);  // 30 s at 200 samples/s, both ends
  // Printed to 6 significant digits.
  EXPECT_NEAR(amplitude, expected.amplitude, 1e-5 * expected.amplitude);
  EXPECT_NEAR(rms, expected.rms, 1e-5 * expected.rms);
  EXPECT_NEAR(frequency, expected.frequency_hz, 1e-5 * expected.frequency_hz);
  EXPECT_NE(out.find("flexmbd_run: cycle of plunge over [30, 60] s: "), std::string::npos) << out;
}

}  // namespace conner_section_test
}  // namespace flexmbd
