// Command-line runner: runs a case without roscore.
//   flexmbd_run --urdf F --config F [--csv F]
// Exit status: 0 success, 1 usage error, 2 bad input (ConfigError), 3 the run failed (SolverError).

#include <cstdio>
#include <memory>
#include <string>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/io/csv_sink.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace {

constexpr char kUsage[] = "usage: flexmbd_run --urdf FILE --config FILE [--csv FILE]\n";

struct Arguments {
  std::string urdf, config, csv;
};

bool Parse(int argc, char** argv, Arguments* args) {
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (k + 1 >= argc) return false;
    const std::string value = argv[++k];
    if (flag == "--urdf") args->urdf = value;
    else if (flag == "--config") args->config = value;
    else if (flag == "--csv") args->csv = value;
    else return false;
  }
  return !args->urdf.empty();
}

void PrintSummary(const flexmbd::Simulation& simulation, const flexmbd::OutputSample& last) {
  std::printf("flexmbd_run: finished at t = %.6g s\n", simulation.state().t);
  std::printf("flexmbd_run: %s\n", simulation.statistics().Summary().c_str());
  std::printf("flexmbd_run: energy kinetic %.6g J, potential %.6g J, external work %.6g J, dissipated %.6g J, "
              "numerical dissipation %.6g J\n",
              last.kinetic, last.potential, last.external_work, last.dissipated, last.numerical_dissipation);
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  if (!Parse(argc, argv, &args)) {
    std::fputs(kUsage, stderr);
    return 1;
  }
  std::unique_ptr<flexmbd::CsvSink> csv;
  try {
    flexmbd::ModelSpec spec = flexmbd::LoadModelSpec(args.urdf, args.config);
    if (!args.csv.empty()) spec.output.csv = args.csv;
    const flexmbd::Model model = flexmbd::BuildModel(spec);
    if (!model.output().csv.empty()) csv = std::make_unique<flexmbd::CsvSink>(model, model.output().csv);
    flexmbd::Simulation simulation(model);
    flexmbd::OutputSample last;
    try {
      simulation.Run([&](const flexmbd::OutputSample& sample) {
        if (csv) csv->Write(sample);
        last = sample;
      });
    } catch (const flexmbd::SolverError& e) {
      if (csv) csv->Close();
      std::fprintf(stderr, "flexmbd_run: run failed: %s\n", e.what());
      std::printf("flexmbd_run: %s\n", simulation.statistics().Summary().c_str());
      return 3;
    }
    if (csv) csv->Close();
    PrintSummary(simulation, last);
  } catch (const flexmbd::ConfigError& e) {
    std::fprintf(stderr, "flexmbd_run: %s\n", e.what());
    return 2;
  }
  return 0;
}
