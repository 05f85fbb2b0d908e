#include "chapters/09_speed_vs_error/report.hpp"

#include "chapters/09_speed_vs_error/plot_svg.hpp"
#include "chapters/09_speed_vs_error/report_csv.hpp"
#include "chapters/09_speed_vs_error/report_markdown.hpp"
#include "chapters/09_speed_vs_error/summary.hpp"
#include "common/output_files.hpp"

namespace tri::ch09 {

ReportFiles render_report(const BenchReport& report) {
  const std::vector<AlgorithmSummary> summaries = summarize(report.rows);
  return {to_csv(report.rows), to_markdown(report, summaries), to_svg(report, summaries)};
}

std::vector<std::filesystem::path> report_paths(const std::filesystem::path& folder) {
  return {folder / csv_file_name, folder / markdown_file_name, folder / svg_file_name};
}

void save_report(const std::filesystem::path& folder, const BenchReport& report,
                 std::ostream& log) {
  const ReportFiles files = render_report(report);
  const auto paths = report_paths(folder);
  OutputTransaction set;
  set.stage(paths[0], bytes_of_text(files.csv));
  set.stage(paths[1], bytes_of_text(files.markdown));
  set.stage(paths[2], bytes_of_text(files.svg));
  set.commit();
  for (const auto& path : paths) log << "wrote " << path.string() << "\n";
}

}  // namespace tri::ch09
