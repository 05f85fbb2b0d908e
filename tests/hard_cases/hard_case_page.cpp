#include "tests/hard_cases/hard_case_page.hpp"

#include <algorithm>
#include <iterator>
#include <map>
#include <sstream>

#include "tests/hard_cases/hard_case_diagram.hpp"

namespace tri::hard_cases {
namespace {

bool no_deviation(const ErrorReport& e) {
  return e.missed == 0 && e.extra == 0 && e.gaps == 0 && e.overdraw == 0 && e.order_dependent == 0;
}

std::string count(std::uint64_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The algorithm names in the matrix's header may break after an underscore (a zero-width space),
// so eighteen columns fit the page.
std::string breakable(const std::string& name) {
  std::string out;
  for (const char ch : name) {
    out += ch;
    if (ch == '_') out += "\u200b";
  }
  return out;
}

// A cell's codes stay on one line (no-break spaces), so "m6 x26 g6" never splits.
std::string unbroken(const std::string& text) {
  std::string out;
  for (const char ch : text) out += ch == ' ' ? std::string("\u00a0") : std::string(1, ch);
  return out;
}

// The anchor GitHub gives the case's heading: its name, which is lower case, digits and '_'.
// The site's Markdown filter gives the heading an id of its own and rewrites the links.
std::string anchor(const HardCase& c) {
  return c.name;
}

}  // namespace

std::string in_words(const Outcome& o) {
  const ErrorReport& e = o.error;
  if (!o.safe) {
    return e.outside_writes > 0
               ? "**unsafe**: " + count(e.outside_writes, "write", "writes") + " outside the canvas"
               : "**unsafe**: input it should refuse was drawn, or the reverse";
  }
  if (no_deviation(e)) return e.rejected > 0 ? "refused" : "exact";
  std::string text;
  const auto part = [&](std::uint64_t n, const char* one, const char* many) {
    if (n == 0) return;
    if (!text.empty()) text += ", ";
    text += count(n, one, many);
  };
  part(e.missed, "missed pixel", "missed pixels");
  part(e.extra, "extra pixel", "extra pixels");
  part(e.gaps, "gap (a covered pixel never drawn)", "gaps (covered pixels never drawn)");
  part(e.overdraw, "pixel drawn too often", "pixels drawn too often");
  part(e.order_dependent, "pixel that changes with the vertex order",
       "pixels that change with the vertex order");
  return text;
}

std::string cell(const Outcome& o) {
  if (!o.safe) return "**unsafe**";
  const ErrorReport& e = o.error;
  if (no_deviation(e)) return e.rejected > 0 ? "refused" : "exact";
  std::ostringstream text;
  const auto part = [&](std::uint64_t n, const char* tag) {
    if (n == 0) return;
    if (text.tellp() > 0) text << ' ';
    text << tag << n;
  };
  part(e.missed, "m");
  part(e.extra, "x");
  part(e.gaps, "g");
  part(e.overdraw, "o");
  part(e.order_dependent, "d");
  return text.str();
}

std::string to_markdown(const std::vector<Outcome>& outcomes, const std::vector<HardCase>& cases) {
  std::vector<std::string> algorithms;
  std::map<std::pair<std::string, std::string>, const Outcome*> table;
  for (const auto& o : outcomes) {
    if (algorithms.empty() || algorithms.back() != o.algorithm) algorithms.push_back(o.algorithm);
    table[{o.case_name, o.algorithm}] = &o;
  }
  std::ostringstream md;
  md << "# Hard cases × algorithms <!-- doxygen: {#hard_cases} -->\n\n"
     << "Every registered algorithm on every hard case of the shared suite "
        "(`tests/hard_cases/hard_cases.cpp`), measured against the exact oracle of chapter 07 on "
        "a 32×32 canvas. The matrix gives the whole picture at a glance; below it, each case has "
        "a section with the reason it is hard, a diagram of its triangles on the pixel grid and "
        "its results in words.\n\n"
     << "The tests forbid **unsafe** for every algorithm (a write outside the canvas, or NaN "
        "input drawn), demand **exact** from every `top-left` algorithm, and pin every other "
        "number in `tests/hard_cases_expected.csv`.\n\n";

  md << "## The matrix\n\n"
     << "How to read a cell:\n\n"
     << "- **exact**: the same pixels as the oracle, in every vertex order.\n"
     << "- **refused**: NaN or infinite input rejected, nothing drawn.\n"
     << "- Otherwise the counts that are not zero, a letter and a number each: "
        "**m** missed pixels, **x** extra pixels, **g** gaps (covered pixels never drawn), "
        "**o** pixels drawn too often (overdraw), **d** pixels that change with the vertex "
        "order. `x26 o1` reads \"26 extra pixels, 1 pixel drawn too often\".\n\n";
  // An algorithm exact (or rightly refusing) on every case gets no column, only a mention, so
  // the columns that tell something fit the page.
  std::vector<std::string> columns, always_exact;
  for (const auto& a : algorithms) {
    const bool exact_everywhere = std::all_of(cases.begin(), cases.end(), [&](const HardCase& c) {
      const auto it = table.find({c.name, a});
      return it != table.end() && it->second->safe && no_deviation(it->second->error);
    });
    (exact_everywhere ? always_exact : columns).push_back(a);
  }
  if (!always_exact.empty()) {
    md << "Exact on every case, so not given a column: ";
    for (std::size_t i = 0; i < always_exact.size(); ++i) {
      md << (i ? ", " : "") << '`' << always_exact[i] << '`';
    }
    md << ".\n\n";
  }
  md << "| case |";
  for (const auto& a : columns) md << " " << breakable(a) << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) md << "---|";
  md << "\n";
  for (const auto& c : cases) {
    md << "| [" << c.name << "](#" << anchor(c) << ") |";
    for (const auto& a : columns) {
      const auto it = table.find({c.name, a});
      md << " " << (it == table.end() ? std::string("–") : unbroken(cell(*it->second))) << " |";
    }
    md << "\n";
  }

  md << "\n## The cases\n\n"
     << "Each diagram shows the pixels around the case's triangles (the whole canvas when a "
        "vertex lies beyond it): grey pixels are the ones the exact oracle covers, the blue lines "
        "the ideal edges, and a red ring marks a pixel centre exactly on an edge, where only a "
        "tie rule can decide.\n";
  for (const auto& c : cases) {
    md << "\n### " << c.name << "\n\n"
       << "**Why it is hard:** " << c.reason << ".\n\n";
    const auto named = named_vertices(c);
    if (!named.empty()) {
      md << "**Vertices:** ";
      for (std::size_t i = 0; i < named.size(); ++i) {
        md << (i ? ", " : "") << named[i].name << " = " << coordinates(named[i].position);
      }
      md << ".\n\n";
    } else {
      md << "**Triangles:** " << c.scene.primitives.size() << " (the diagram shows them all).\n\n";
    }
    if (reaches_beyond_canvas(c)) {
      md << "**Beyond the canvas:** the diagram shows the 32×32 canvas and the part of the "
            "triangles inside it; the vertices above are the real ones.\n\n";
    }
    md << "![" << c.name << ": its triangles on the pixel grid](" << diagram_name(c) << ".svg)\n\n";
    // The results, grouped: the algorithms that deviate, then one line for all the others.
    std::vector<std::pair<std::string, std::vector<std::string>>> groups;
    for (const auto& a : algorithms) {
      const auto it = table.find({c.name, a});
      if (it == table.end()) continue;
      const std::string words = in_words(*it->second);
      auto group = std::find_if(groups.begin(), groups.end(),
                                [&](const auto& g) { return g.first == words; });
      if (group == groups.end()) {
        groups.push_back({words, {}});
        group = std::prev(groups.end());
      }
      group->second.push_back(a);
    }
    md << "**Results:**\n\n";
    for (const auto& [words, names] : groups) {
      const bool plain = words == "exact" || words == "refused";
      if (plain && names.size() * 2 > algorithms.size()) continue;  // the majority, last
      md << "- " << words << ": ";
      for (std::size_t i = 0; i < names.size(); ++i)
        md << (i ? ", " : "") << '`' << names[i] << '`';
      md << "\n";
    }
    for (const auto& [words, names] : groups) {
      const bool plain = words == "exact" || words == "refused";
      if (!plain || names.size() * 2 <= algorithms.size()) continue;
      md << "- " << words << ": "
         << (names.size() == algorithms.size() ? "every algorithm"
                                               : "the other " + std::to_string(names.size()))
         << "\n";
    }
  }
  return md.str();
}

}  // namespace tri::hard_cases
