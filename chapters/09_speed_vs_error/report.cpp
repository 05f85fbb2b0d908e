#include "report.hpp"

#include "plot_svg.hpp"
#include "report_csv.hpp"
#include "report_markdown.hpp"
#include "summary.hpp"

namespace tri::ch09 {

ReportFiles render_report(const BenchReport& report) {
  const std::vector<AlgorithmSummary> summaries = summarize(report.rows);
  return {to_csv(report.rows), to_markdown(report, summaries), to_svg(report, summaries)};
}

void save_report(FigureWriter& figures, const BenchReport& report) {
  const ReportFiles files = render_report(report);
  figures.save_text(csv_file_name, files.csv);
  figures.save_text(markdown_file_name, files.markdown);
  figures.save_text(svg_file_name, files.svg);
}

}  // namespace tri::ch09
