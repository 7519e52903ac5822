// summary.cpp — one table over every benchmark family, and the tables in the docs.
//
//   summary DIR               reads DIR/<family>.csv (all but summary.csv), prints one table,
//                             writes DIR/summary.csv (same columns as each family's CSV)
//   summary DIR --markdown F  also rewrites, in the Markdown file F, every section between
//                             "<!-- bench-table: FAMILY -->" and "<!-- end bench-table -->"
//                             with that family's rows as a Markdown table (make docs-tables)
// Exit status 1 with the reason on stderr when a CSV is malformed or a file cannot be
// written; a family named in F but not measured gets a "not measured" line.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../common/bench.h"

namespace {

std::string read_text(const std::string &path, bool &ok) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    ok = bool(in) || in.eof();
    return s.str();
}

std::string cell(double v) {
    if (std::isnan(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string markdown_table(const std::vector<bench::row> &rows) {
    const std::vector<double> ratio = bench::ratios_to_faithful(rows);
    std::string out = "| variant | kind | time median (min-max) | error mean / max | vs faithful |\n"
                      "|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const bench::row &r = rows[i];
        std::string variant = r.variant;
        std::replace(variant.begin(), variant.end(), '|', '/');
        out += "| " + variant + " | " + r.kind + " | " + cell(r.time.median) + " (" + cell(r.time.min) + "-" +
               cell(r.time.max) + ") " + r.unit + " | " + cell(r.error_mean) + " / " + cell(r.error_max) + " " +
               (std::isnan(r.error_mean) && std::isnan(r.error_max) ? "" : r.error_unit) + " | " +
               (std::isnan(ratio[i]) ? std::string("-") : cell(ratio[i]) + "x") + " |\n";
    }
    return out;
}

// Replaces each marked section of `doc` with the family's table; false if a marker is unclosed.
bool fill_markdown(std::string &doc, const std::vector<bench::row> &rows, std::string &why) {
    const std::string open = "<!-- bench-table: ", close = "<!-- end bench-table -->";
    for (std::size_t pos = doc.find(open); pos != std::string::npos; pos = doc.find(open, pos + 1)) {
        const std::size_t name_end = doc.find(" -->", pos);
        const std::size_t end = doc.find(close, pos);
        if (name_end == std::string::npos || end == std::string::npos || name_end > end) {
            why = "unclosed '" + open + "' section";
            return false;
        }
        const std::string family = doc.substr(pos + open.size(), name_end - pos - open.size());
        std::vector<bench::row> mine;
        for (const bench::row &r : rows)
            if (r.family == family) mine.push_back(r);
        const std::string table =
            mine.empty() ? "(not measured: run `make bench` then `make docs-tables`)\n" : markdown_table(mine);
        const std::size_t body = name_end + 4;
        doc.replace(body, end - body, "\n" + table);
    }
    return true;
}

}  // namespace

int main(int argc, char **argv) {
    if (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--markdown")) {
        std::fprintf(stderr, "usage: %s DIR [--markdown FILE.md]\n", argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    std::vector<std::string> paths;
    std::error_code ec;
    for (const auto &entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".csv" && entry.path().filename() != "summary.csv")
            paths.push_back(entry.path().string());
    if (ec) {
        std::fprintf(stderr, "summary: cannot list '%s': %s\n", dir.c_str(), ec.message().c_str());
        return 1;
    }
    std::sort(paths.begin(), paths.end());
    std::vector<bench::row> all;
    for (const std::string &p : paths) {
        bool ok = false;
        const std::string text = read_text(p, ok);
        const auto rows = bench::parse_csv(text, p);
        if (!ok || !rows) {
            std::fprintf(stderr, "summary: %s\n", ok ? rows.message().c_str() : (p + ": cannot read").c_str());
            return 1;
        }
        all.insert(all.end(), rows->begin(), rows->end());
    }
    std::printf("\n== summary of %zu families, %zu variants (time: median [min-max]; error vs reference)\n%s",
                paths.size(), all.size(), bench::table_text(all).c_str());
    const std::string csv = bench::csv_text(all), out = dir + "/summary.csv";
    if (const tiny3d::status s = tiny3d::write_file_atomic(out, csv.data(), csv.size()); !s) {
        std::fprintf(stderr, "summary: %s\n", s.message().c_str());
        return 1;
    }
    std::printf("wrote %s\n", out.c_str());
    if (argc == 4) {
        const std::string md_path = argv[3];
        bool ok = false;
        std::string doc = read_text(md_path, ok);
        std::string why;
        if (!ok || !fill_markdown(doc, all, why)) {
            std::fprintf(stderr, "summary: %s: %s\n", md_path.c_str(), ok ? why.c_str() : "cannot read");
            return 1;
        }
        if (const tiny3d::status s = tiny3d::write_file_atomic(md_path, doc.data(), doc.size()); !s) {
            std::fprintf(stderr, "summary: %s\n", s.message().c_str());
            return 1;
        }
        std::printf("updated the tables in %s\n", md_path.c_str());
    }
    return 0;
}
