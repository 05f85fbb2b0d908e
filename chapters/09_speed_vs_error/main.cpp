// Chapter 09's report: every registered algorithm on the same scene suites, timed and compared
// with the exact oracle; writes 09_report.csv, 09_report.md and 09_speed_vs_error.svg.
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "figures.hpp"
#include "measure.hpp"
#include "registry.hpp"
#include "report.hpp"
#include "suites.hpp"

namespace {

// The registered algorithms named in a comma-separated list (all of them for an empty list).
std::vector<tri::TriangleAlgorithm> selected_algorithms(const std::string& names) {
  const std::vector<tri::TriangleAlgorithm> all = tri::registered_algorithms();
  if (names.empty()) return all;
  std::vector<tri::TriangleAlgorithm> chosen;
  std::istringstream list(names);
  std::string name;
  while (std::getline(list, name, ',')) {
    const tri::TriangleAlgorithm* algorithm = tri::find_algorithm(all, name);
    if (algorithm == nullptr) {
      throw tri::UsageError("no registered algorithm is named '" + name + "' (see raster --list)");
    }
    chosen.push_back(*algorithm);
  }
  return chosen;
}

}  // namespace

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "09_speed_vs_error",
      "Chapter 09, speed against error: draws the same scene suites with every registered\n"
      "algorithm, times them (warm-up, median of repeated samples, beside a std::fill ceiling)\n"
      "and measures their error against the exact oracle. Writes 09_report.csv (every\n"
      "measurement), 09_report.md (one row per algorithm, the machine) and 09_speed_vs_error.svg\n"
      "(the plot). Quick by default (about a minute on two cores); --full for the complete sweep.",
      {{"out", "DIR", "folder for the report (default: out)"},
       {"full", "", "complete sweep: 512x512 canvas, 100,000-triangle mesh, longer samples"},
       {"only", "NAMES", "measure only these algorithms (comma-separated registry names)"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& args) {
        const auto size =
            args.has("full") ? tri::ch09::SuiteSize::full : tri::ch09::SuiteSize::quick;
        const auto algorithms = selected_algorithms(args.value_or("only", ""));
        const tri::ch09::BenchSettings settings = tri::ch09::bench_settings(size);
        std::cout << "09_speed_vs_error: " << algorithms.size() << " algorithms x "
                  << settings.scenes.size() << " scenes, " << tri::ch09::size_name(size)
                  << " setting\n";
        const tri::ch09::BenchReport report = tri::ch09::run_benchmark(
            algorithms, settings, tri::ch09::describe_machine(), std::cout);
        tri::FigureWriter figures(args.value_or("out", "out"), std::cout);
        tri::ch09::save_report(figures, report);
        return 0;
      });
}
