// bench.cpp — timing, table, CSV and chart output shared by every benchmark program.
#include "bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "canvas.h"
#include "chart.h"

namespace bench {
namespace {

constexpr const char *usage_text =
    "usage: %s [--out DIR] [--quick]\n"
    "  --out DIR   where <family>.csv and <family>.pgm go (default build/bench)\n"
    "  --quick     fewer repeats and smaller inputs (for valgrind runs)\n";

std::string format_number(double v) {
    if (std::isnan(v)) return "nan";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// One CSV text field: never empty, never multi-line, quoted when needed.
std::string csv_field(std::string_view text) {
    std::string s(text.empty() ? std::string_view("-") : text);
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    if (s.find_first_of(",\"") == std::string::npos) return s;
    std::string quoted = "\"";
    for (const char c : s) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

// Splits one CSV record (no embedded newlines) into fields; false on a broken quote.
bool split_csv_record(std::string_view line, std::vector<std::string> &fields) {
    fields.clear();
    std::string field;
    bool in_quotes = false, was_quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (in_quotes) {
            if (c != '"') field += c;
            else if (i + 1 < line.size() && line[i + 1] == '"') { field += '"'; ++i; }
            else in_quotes = false;
        } else if (c == '"' && field.empty() && !was_quoted) {
            in_quotes = was_quoted = true;
        } else if (c == ',') {
            fields.push_back(field);
            field.clear();
            was_quoted = false;
        } else {
            field += c;
        }
    }
    fields.push_back(field);
    return !in_quotes;
}

bool parse_number(const std::string &text, double &value) {
    if (text.empty()) return false;
    char *end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
}

std::string time_cell(const row &r) {
    return format_number(r.time.median) + " [" + format_number(r.time.min) + "-" +
           format_number(r.time.max) + "] " + r.unit;
}

std::string error_cell(const row &r) {
    if (std::isnan(r.error_mean) && std::isnan(r.error_max)) return "-";
    return format_number(r.error_mean) + " / " + format_number(r.error_max) + " " + r.error_unit;
}

std::string ratio_cell(double ratio) {
    if (std::isnan(ratio)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3gx", ratio);
    return buf;
}

// The distinct values of one text field over the rows, joined by " / ".
std::string distinct_joined(const std::vector<row> &rows, std::string row::*field) {
    std::vector<std::string> seen;
    for (const row &r : rows)
        if (std::find(seen.begin(), seen.end(), r.*field) == seen.end()) seen.push_back(r.*field);
    std::string out;
    for (const std::string &s : seen) out += (out.empty() ? "" : " / ") + s;
    return out;
}

constexpr int chart_width = 800, chart_height = 500;

// A legend name, plus " [kind]" when the name does not say it.
std::string with_kind(const std::string &name, const std::string &kind) {
    return name.find(kind) == std::string::npos ? name + " [" + kind + "]" : name;
}

// The row's unit without its tag ("ns/px T=1" with tag "T=1" → "ns/px"): a series spans
// the tags, so the axis title names the unit once.
std::string unit_of(const row &r) {
    const std::string suffix = " " + r.tag;
    if (!r.tag.empty() && r.unit.size() > suffix.size() &&
        r.unit.compare(r.unit.size() - suffix.size(), suffix.size(), suffix) == 0)
        return r.unit.substr(0, r.unit.size() - suffix.size());
    return r.unit;
}

}  // namespace

tiny3d::chart_spec chart_of(const std::vector<row> &rows, const std::string &title) {
    tiny3d::chart_spec spec;
    spec.title = title;
    std::vector<row> units = rows;
    for (row &r : units) r.unit = unit_of(r);
    spec.x_title = "time per unit, " + distinct_joined(units, &row::unit) + " (median; bar: min-max)";
    spec.y_title = "error vs reference, " + distinct_joined(rows, &row::error_unit) + " (mean; bar: to max)";
    for (const row &r : rows) {
        tiny3d::chart_point p;
        p.label = with_kind(r.variant, r.kind);
        if (!r.series.empty()) p.series = with_kind(r.series, r.kind);
        p.tag = r.tag;
        p.x = r.time.median;
        p.x_lo = r.time.min;
        p.x_hi = r.time.max;
        p.y = std::isfinite(r.error_mean) ? r.error_mean : r.error_max;
        if (std::isnan(p.y) && r.kind == "reference") p.y = 0;  // exact by definition
        if (std::isfinite(r.error_mean) && std::isfinite(r.error_max)) {
            p.y_lo = r.error_mean;
            p.y_hi = r.error_max;
        }
        spec.points.push_back(std::move(p));
    }
    return spec;
}

tiny3d::status write_chart(const std::string &path, const tiny3d::chart_spec &spec) {
    auto canvas = tiny3d::make_canvas(chart_width, chart_height);
    if (!canvas) return canvas.to_status();
    const auto layout = tiny3d::draw_chart(**canvas, spec);
    if (!layout) return layout.to_status();
    return tiny3d::save_pgm(**canvas, path);
}

tiny3d::status write_chart(const std::string &path, const std::vector<row> &rows, const std::string &title) {
    return write_chart(path, chart_of(rows, title));
}

int write_workload_charts(const options &o, const std::vector<row> &rows, const std::vector<workload_chart> &charts) {
    for (const workload_chart &c : charts) {
        std::vector<row> picked;
        for (const row &r : rows)
            if (r.variant.rfind(c.prefix, 0) == 0) {
                picked.push_back(r);
                picked.back().variant = r.variant.substr(c.prefix.size());
            }
        const std::string path = o.out_dir + "/" + c.file + ".pgm";
        const tiny3d::status st = picked.empty() ? tiny3d::status(tiny3d::error{"", 0, -1, "no '" + c.prefix + "' rows"})
                                                 : write_chart(path, picked, c.title);
        if (!st) {
            std::fprintf(stderr, "bench: %s: %s\n", path.c_str(), st.message().c_str());
            return 1;
        }
        std::printf("wrote %s\n", path.c_str());
    }
    return 0;
}

// The warm-up and timed runs of one measure_ns call. Kept out of line under its own
// name so `make bench-callgrind` (tests/bench/callgrind.sh) can count its instructions
// alone: it collects only inside timed_runs and dumps before each measure_ns call.
[[gnu::noinline]] static void timed_runs(const std::function<void()> &fn, std::vector<double> &per_unit, double units) {
    using clock = std::chrono::steady_clock;
    fn();  // warm-up: caches, page faults, lazy allocation
    for (double &t : per_unit) {
        const auto start = clock::now();
        fn();
        const auto stop = clock::now();
        t = std::chrono::duration<double, std::nano>(stop - start).count() / units;
    }
}

timing measure_ns(int repeats, double work_units, const std::function<void()> &fn) {
    const int runs = std::max(repeats, 1);
    const double units = work_units > 0 ? work_units : 1.0;
    std::vector<double> per_unit(std::size_t(runs), 0.0);
    timed_runs(fn, per_unit, units);
    return summarise(std::move(per_unit));
}

timing summarise(std::vector<double> values) {
    if (values.empty()) return {NAN, NAN, NAN};
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

options parse_options(int argc, char **argv) {
    options o;
    const char *program = argc > 0 ? argv[0] : "bench";
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--out" && i + 1 < argc) {
            o.out_dir = argv[++i];
        } else if (arg == "--quick") {
            o.quick = true;
        } else if (arg == "--help" || arg == "-h") {
            std::printf(usage_text, program);
            std::exit(0);
        } else {
            std::fprintf(stderr, "%s: %s '%s'\n", program,
                         arg == "--out" ? "missing folder after" : "unknown argument", argv[i]);
            std::fprintf(stderr, usage_text, program);
            std::exit(2);
        }
    }
    if (o.out_dir.empty()) {
        std::fprintf(stderr, "%s: --out needs a non-empty folder\n", program);
        std::exit(2);
    }
    return o;
}

const std::vector<std::string> &csv_columns() {
    static const std::vector<std::string> columns = {
        "family",    "variant",   "kind",       "unit",       "time_median", "time_min",
        "time_max",  "error_mean", "error_max", "error_unit", "ratio_to_faithful", "note"};
    return columns;
}

std::vector<double> ratios_to_faithful(const std::vector<row> &rows) {
    std::vector<double> ratios(rows.size(), std::nan(""));
    const auto same_group = [&](std::size_t f, std::size_t i) {
        return rows[f].kind == "faithful" && rows[f].family == rows[i].family && rows[f].unit == rows[i].unit;
    };
    for (std::size_t i = 0; i < rows.size(); ++i) {
        // The nearest faithful row listed at or before this one, else the first after it.
        std::size_t f = i + 1;
        while (f-- > 0)
            if (same_group(f, i)) break;
        if (f == std::size_t(-1))
            for (f = i + 1; f < rows.size() && !same_group(f, i); ++f) {}
        if (f < rows.size() && rows[f].time.median > 0) ratios[i] = rows[i].time.median / rows[f].time.median;
    }
    return ratios;
}

std::string csv_text(const std::vector<row> &rows) {
    std::string out;
    for (const std::string &c : csv_columns()) out += (out.empty() ? "" : ",") + c;
    out += '\n';
    const std::vector<double> ratios = ratios_to_faithful(rows);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const row &r = rows[i];
        const std::string fields[] = {
            csv_field(r.family),          csv_field(r.variant),          csv_field(r.kind),
            csv_field(r.unit),            format_number(r.time.median),  format_number(r.time.min),
            format_number(r.time.max),    format_number(r.error_mean),   format_number(r.error_max),
            csv_field(r.error_unit),      format_number(ratios[i]),      csv_field(r.note)};
        std::string line;
        for (const std::string &f : fields) line += (line.empty() ? "" : ",") + f;
        out += line + '\n';
    }
    return out;
}

tiny3d::result<std::vector<row>> parse_csv(const std::string &text, const std::string &path) {
    std::vector<row> rows;
    std::vector<std::string> f;
    const std::size_t n_columns = csv_columns().size();
    long line_no = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + pos, end - pos);
        pos = end + 1;
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (!split_csv_record(line, f)) return tiny3d::error{path, line_no, -1, "unterminated quote"};
        if (line_no == 1) {
            if (f != csv_columns()) return tiny3d::error{path, 1, -1, "not a benchmark CSV (unexpected header)"};
            continue;
        }
        if (line.empty()) continue;
        if (f.size() != n_columns)
            return tiny3d::error{path, line_no, -1,
                                 "expected " + std::to_string(n_columns) + " fields, found " +
                                     std::to_string(f.size())};
        row r;
        r.family = f[0];
        r.variant = f[1];
        r.kind = f[2];
        r.unit = f[3];
        double *numbers[] = {&r.time.median, &r.time.min, &r.time.max, &r.error_mean, &r.error_max};
        for (std::size_t k = 0; k < 5; ++k)
            if (!parse_number(f[4 + k], *numbers[k]))
                return tiny3d::error{path, line_no, -1,
                                     "column '" + csv_columns()[4 + k] + "': not a number: '" + f[4 + k] + "'"};
        r.error_unit = f[9];
        r.note = f[11] == "-" ? "" : f[11];
        rows.push_back(std::move(r));
    }
    if (line_no == 0) return tiny3d::error{path, 0, -1, "empty file"};
    return rows;
}

std::string table_text(const std::vector<row> &rows) {
    const std::vector<double> ratios = ratios_to_faithful(rows);
    std::vector<std::vector<std::string>> cells;
    cells.push_back({"family", "variant", "kind", "time median [min-max]", "error mean / max", "vs faithful"});
    for (std::size_t i = 0; i < rows.size(); ++i)
        cells.push_back({rows[i].family, rows[i].variant, rows[i].kind, time_cell(rows[i]),
                         error_cell(rows[i]), ratio_cell(ratios[i])});
    std::vector<std::size_t> width(cells[0].size(), 0);
    for (const auto &line : cells)
        for (std::size_t c = 0; c < line.size(); ++c) width[c] = std::max(width[c], line[c].size());
    std::string out;
    for (std::size_t l = 0; l < cells.size(); ++l) {
        for (std::size_t c = 0; c < cells[l].size(); ++c) {
            out += cells[l][c];
            if (c + 1 < cells[l].size()) out += std::string(width[c] - cells[l][c].size() + 2, ' ');
        }
        out += '\n';
        if (l == 0) {
            std::size_t total = 0;
            for (std::size_t w : width) total += w + 2;
            out += std::string(total - 2, '-') + '\n';
        }
    }
    return out;
}

int report(const options &o, const std::string &family, const std::vector<row> &rows,
           const std::string &chart_title) {
    const auto fail = [&](const std::string &why) {
        std::fprintf(stderr, "bench %s: %s\n", family.c_str(), why.c_str());
        return 1;
    };
    if (rows.empty()) return fail("no rows to report");
    for (const row &r : rows)
        if (r.family != family) return fail("row '" + r.variant + "' belongs to family '" + r.family + "'");
    std::printf("%s\n%s", chart_title.c_str(), table_text(rows).c_str());
    std::error_code ec;
    std::filesystem::create_directories(o.out_dir, ec);
    if (ec) return fail("cannot create folder '" + o.out_dir + "': " + ec.message());
    const std::string csv = csv_text(rows);
    const std::string csv_path = o.out_dir + "/" + family + ".csv";
    if (const tiny3d::status s = tiny3d::write_file_atomic(csv_path, csv.data(), csv.size()); !s)
        return fail(s.message());
    const std::string chart_path = o.out_dir + "/" + family + ".pgm";
    if (const tiny3d::status s = write_chart(chart_path, rows, chart_title); !s) return fail(s.message());
    std::printf("wrote %s and %s\n", csv_path.c_str(), chart_path.c_str());
    std::fflush(stdout);
    return 0;
}

}  // namespace bench
