// bench.h — shared helpers for the speed-against-accuracy benchmarks (tests/bench/*.cpp).
//
// A benchmark program measures, on the same input, the faithful variant (the libtiny3d
// report's method), an exact reference and one or more fast paths. For each it records
// the time per unit of work (median over repeats, with min and max) and the error against
// the reference, then calls bench::report(), which
//   * prints a table (with each row's time as a ratio to the faithful row of its group),
//   * writes OUT/<family>.csv (header line + one row per variant, no empty fields),
//   * draws OUT/<family>.pgm: log-log chart of time (x) against error (y), one marker per
//     row, drawn with the benchmarks' chart code (common/chart.h).
//
//   int main(int argc, char **argv) {
//       const bench::options o = bench::parse_options(argc, argv);
//       std::vector<bench::row> rows;
//       const bench::timing t = bench::measure_ns(o.quick ? 3 : 15, pixels, [&] { ... });
//       rows.push_back({"lines", "faithful DDA splat T=1.5", "faithful", "ns/px", t,
//                       err_mean, err_max, "abs intensity", ""});
//       return bench::report(o, "lines", rows, "Lines: time per pixel vs intensity error");
//   }
//
// Timings are wall-clock (std::chrono::steady_clock); on a busy machine prefer instruction
// counts (`make bench-callgrind`) to compare variants. Never use these in tests.
#ifndef TINY3D_BENCH_H
#define TINY3D_BENCH_H

#include <functional>
#include <string>
#include <vector>

#include "chart.h"
#include "tiny3d_result.h"

namespace bench {

// Time per unit of work, in the unit the caller states in row::unit (measure_ns gives ns).
struct timing {
    double median, min, max;
};

// Runs fn() once to warm caches, then `repeats` more times (at least 1), timing each run;
// returns elapsed nanoseconds / work_units for the median, fastest and slowest run.
// work_units ≤ 0 is treated as 1. Keep fn's results alive with bench::keep(x).
timing measure_ns(int repeats, double work_units, const std::function<void()> &fn);

// The median, fastest and slowest of `values` (at least one; sorted here).
timing summarise(std::vector<double> values);

// Optimization barrier: the compiler must assume `value` is read, so the computation that
// produced it cannot be removed.
template <class T>
void keep(const T &value) {
#if defined(__GNUC__) || defined(__clang__)
    asm volatile("" : : "g"(&value) : "memory");
#else
    static_cast<void>(*static_cast<const volatile char *>(static_cast<const volatile void *>(&value)));
#endif
}

struct row {
    std::string family;      // e.g. "lines"
    std::string variant;     // e.g. "faithful DDA splat T=1.5"
    std::string kind;        // "faithful" | "reference" | "fast" | "other"
    std::string unit;        // e.g. "ns/px"
    timing time;
    double error_mean;       // against the reference; NaN if not applicable
    double error_max;
    std::string error_unit;  // e.g. "abs intensity", "rel", "px"
    std::string note;        // optional
    // Chart only (not in the table or CSV): rows with the same non-empty `series` (one
    // method across sizes or widths) are one line with one legend entry; `tag` (e.g.
    // "T=1.5") labels the row's point on it. Empty series: the row is its own entry.
    std::string series = {};
    std::string tag = {};
};

struct options {
    std::string out_dir = "build/bench";
    bool quick = false;  // fewer repeats / smaller inputs (used under valgrind)
};

// Parses --out DIR and --quick (also --help). On an unknown or incomplete argument it
// prints the problem and the usage on stderr and exits with status 2 (benchmark programs
// are command-line tools; the library itself never exits).
options parse_options(int argc, char **argv);

// The ratio column compares each row with a faithful row of the same family and the same
// time unit: the nearest one listed at or before it (so a benchmark that measures several
// workloads lists each workload's faithful row first), else the first one after it. It is
// row.time.median / faithful.time.median; "-" in the table and "nan" in the CSV when the
// family has no faithful row in that unit.
//
// Prints the table on stdout, creates out_dir if needed, writes out_dir/<family>.csv and
// out_dir/<family>.pgm atomically. Returns 0, or prints the error on stderr and returns 1
// (use it as main's result). An empty `rows` or a row whose family differs from `family`
// is an error.
int report(const options &o, const std::string &family, const std::vector<row> &rows,
           const std::string &chart_title);

// ---- pieces of report(), exposed for tests/chart_test.cpp and the summary tool ----------

// The CSV columns, in order (also the header line).
const std::vector<std::string> &csv_columns();
// Header line + one line per row, "\n"-terminated. Numbers in %.6g ("nan" when not a
// number); text fields quoted ("" for a quote) when they contain a comma or a quote;
// newlines in text become spaces (one record per line); an empty text field is written
// as "-", so no field is ever empty.
std::string csv_text(const std::vector<row> &rows);
// Ratio of each row's median time to its faithful row's median (see report()).
std::vector<double> ratios_to_faithful(const std::vector<row> &rows);
// The printed table (also used by the summary tool).
std::string table_text(const std::vector<row> &rows);
// The chart report() draws: x = time median (whisker min..max), y = error mean (whisker
// mean..max; error max when there is no mean; a reference row without error is at 0, drawn
// on the axis floor); legend = variant, plus " [kind]" when the
// variant's name does not say it; rows of one series share one entry (the series name).
tiny3d::chart_spec chart_of(const std::vector<row> &rows, const std::string &title);
// Draws chart_of(rows, title) on an 800 × 500 canvas and saves it as PGM at `path`.
tiny3d::status write_chart(const std::string &path, const std::vector<row> &rows, const std::string &title);
// Draws any chart on the same 800 × 500 canvas and saves it as PGM at `path` (for a
// family's extra charts, e.g. frame time against triangle count).
tiny3d::status write_chart(const std::string &path, const tiny3d::chart_spec &spec);
// A family measuring several workloads, each in its own unit, gets one readable chart
// per workload: the rows whose variant starts with `prefix` (the prefix taken off their
// legend names), drawn as report() draws its chart and saved as OUT/<file>.pgm (a file
// named after the family replaces report()'s chart). Returns 0, or prints the error on
// stderr and returns 1 (also when no row matches a prefix).
struct workload_chart {
    std::string prefix, file, title;
};
int write_workload_charts(const options &o, const std::vector<row> &rows, const std::vector<workload_chart> &charts);
// Reads csv_text's format back (the ratio column is recomputed, not read). Errors name
// `path` and the 1-based line: wrong header, wrong field count, a number that is not one.
tiny3d::result<std::vector<row>> parse_csv(const std::string &text, const std::string &path);

}  // namespace bench

#endif
