// report_table.h -- one table of the report (report.h), rendered as Markdown
// and as HTML from the same cells, and the text helpers its cells use.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace lb::experiments::report {

// A cell's `sort` is the number the HTML table sorts by (NaN: by text).
struct Cell {
    std::string text;
    double sort = NAN;
};

struct Table {
    std::string title, note;  // note: Markdown inline (`code`, **bold**)
    std::vector<std::string> head;
    std::vector<std::vector<Cell>> rows;
    std::string empty;  // said instead of the table when it has no rows
};

inline Cell num(double v, std::string text) { return {std::move(text), std::isfinite(v) ? v : NAN}; }

// Text from the records (luminaire names, SPECs, the run's context) as
// literal Markdown: every character Markdown or HTML would read as markup is
// backslash-escaped (CommonMark), line breaks become spaces (a table row is
// one line).
std::string mdLiteral(const std::string& s);

}  // namespace lb::experiments::report
