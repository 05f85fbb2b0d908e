#include "chapters/09_speed_vs_error/report.hpp"

#include "chapters/09_speed_vs_error/coverage_report.hpp"
#include "chapters/09_speed_vs_error/plot_svg.hpp"
#include "chapters/09_speed_vs_error/report_csv.hpp"
#include "chapters/09_speed_vs_error/report_markdown.hpp"
#include "chapters/09_speed_vs_error/summary.hpp"
#include "common/output_files.hpp"

namespace tri::ch09 {

ReportFiles render_report(const BenchReport& report, const CoverageReport& coverage) {
  const std::vector<AlgorithmSummary> summaries = summarize(report.rows);
  const std::vector<CoverageSummary> coverage_summaries =
      summarize_coverage(coverage.rows, report.rows);
  const std::string subtitle = std::string(size_name(report.size)) + " setting, " +
                               std::to_string(report.width) + "×" + std::to_string(report.height) +
                               " canvas, " + report.machine.cpu_model + " (" +
                               std::to_string(report.machine.threads) + " threads), " +
                               report.machine.compiler + ", " + report.machine.build_type;
  return {to_csv(report.rows),
          to_markdown(report, summaries) +
              coverage_markdown(coverage_summaries, coverage.rows, coverage.peer_status),
          to_svg(report, summaries), coverage_csv(coverage.rows),
          coverage_svg(coverage_summaries, subtitle)};
}

std::vector<std::filesystem::path> report_paths(const std::filesystem::path& folder) {
  return {folder / csv_file_name, folder / markdown_file_name, folder / svg_file_name,
          folder / coverage_csv_file_name, folder / coverage_svg_file_name};
}

void save_report(const std::filesystem::path& folder, const BenchReport& report,
                 const CoverageReport& coverage, std::ostream& log) {
  const ReportFiles files = render_report(report, coverage);
  const auto paths = report_paths(folder);
  OutputTransaction set;
  set.stage(paths[0], bytes_of_text(files.csv));
  set.stage(paths[1], bytes_of_text(files.markdown));
  set.stage(paths[2], bytes_of_text(files.svg));
  set.stage(paths[3], bytes_of_text(files.coverage_csv));
  set.stage(paths[4], bytes_of_text(files.coverage_svg));
  set.commit();
  for (const auto& path : paths) log << "wrote " << path.string() << "\n";
}

}  // namespace tri::ch09
