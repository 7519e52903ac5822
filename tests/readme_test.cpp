// readme_test.cpp — README.md (and the program commands in documentation/*.md) checked
// against the programs themselves: their --help output is the source of truth.
//
// The programs are the demo/*.cpp of the source tree, built as $BUILD/demo/NAME (make test
// builds them first; the plain, sanitizer and portable runs all read the same plain
// programs of their BUILD). An option is a token `--name` (lower case, digits, '-'; an
// upper-case placeholder such as `--NAME` is not one); a program lists an option when a
// line of its --help starts with two spaces and the option. Tests run from the checkout's
// top folder, where README.md and documentation/ are.
//
// Checked:
//  * every option README.md names is listed by some program's --help (an option of another
//    tool, e.g. pkg-config's --cflags, only on a line that names that tool);
//  * every program README.md names — build/demo/NAME, a row of the demos table, a program
//    in the options table's "taken by" column — exists, and every program has a row in
//    the demos table;
//  * each row of the options table: every program it names lists each of its options, and
//    no other program does (unless the row says "every program");
//  * every option a program lists is named somewhere in README.md;
//  * in README.md and documentation/*.md, a command for a program (a code line or inline
//    code holding `build/demo/NAME …`, or inline code starting with NAME) uses only
//    options that program's --help lists.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"

using namespace program_runner;

namespace {

// Options of other tools a README line may name, with the tool that line must name.
const std::vector<std::pair<std::string, std::string>> foreign_options = {
    {"--cflags", "pkg-config"},
    {"--libs", "pkg-config"},
};

bool option_char(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; }
bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

struct token {
    std::string text;
    std::size_t at;  // offset in the text it was found in
};

// Every `--name` in text: "--" not preceded by a word character or '-', then a lower-case
// letter, then letters, digits and '-' (a trailing '-' dropped).
std::vector<token> option_tokens(const std::string &text) {
    std::vector<token> found;
    for (std::size_t i = 0; i + 2 < text.size(); ++i) {
        if (text[i] != '-' || text[i + 1] != '-' || !(text[i + 2] >= 'a' && text[i + 2] <= 'z')) continue;
        if (i > 0 && (word_char(text[i - 1]) || text[i - 1] == '-')) continue;
        std::size_t end = i + 2;
        while (end < text.size() && option_char(text[end])) ++end;
        while (text[end - 1] == '-') --end;
        found.push_back({text.substr(i, end - i), i});
        i = end - 1;
    }
    return found;
}

std::vector<std::string> lines_of(const std::string &text) {
    std::vector<std::string> lines;
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        lines.push_back(text.substr(at, end - at));
        at = end + 1;
    }
    return lines;
}

std::string trimmed(const std::string &s) {
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

// The programs: demo/*.cpp of the source tree.
const std::vector<std::string> &programs() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        std::error_code ec;
        for (const auto &e : fs::directory_iterator("demo", ec))
            if (e.is_regular_file() && e.path().extension() == ".cpp") n.push_back(e.path().stem().string());
        std::sort(n.begin(), n.end());
        return n;
    }();
    return names;
}

bool is_program(const std::string &name) {
    return std::find(programs().begin(), programs().end(), name) != programs().end();
}

// Program → the options its --help lists (empty set for a program that is not built).
const std::map<std::string, std::set<std::string>> &help_options() {
    static const std::map<std::string, std::set<std::string>> options = [] {
        std::map<std::string, std::set<std::string>> o;
        for (const std::string &p : programs()) {
            std::set<std::string> &listed = o[p];
            if (!fs::exists(demo_path(p))) continue;
            temp_dir logs;
            const run_result r = run(demo_path(p), {"--help"}, logs.path);
            if (r.exit_code != 0) continue;
            for (const std::string &line : lines_of(r.out)) {
                if (line.rfind("  --", 0) != 0) continue;
                const std::vector<token> t = option_tokens(line.substr(2));
                if (!t.empty() && t.front().at == 0) listed.insert(t.front().text);
            }
        }
        return o;
    }();
    return options;
}

bool takes(const std::string &program, const std::string &option) {
    const auto it = help_options().find(program);
    return it != help_options().end() && it->second.count(option) != 0;
}

// The checks need the source tree's files and every program built.
bool ready(const std::string &file) {
    const bool have_file = fs::exists(file);
    CHECK_MSG(have_file, file + " not found (tests run from the checkout's top folder)");
    CHECK_MSG(!programs().empty(), "no demo/*.cpp found (tests run from the checkout's top folder)");
    bool all_built = true;
    for (const std::string &p : programs()) {
        const bool ok = fs::exists(demo_path(p)) && !help_options().at(p).empty();
        CHECK_MSG(ok, demo_path(p) + " is not built or its --help lists no option (make test builds the programs first)");
        all_built = all_built && ok;
    }
    return have_file && all_built && !programs().empty();
}

// A markdown table: its header cells and its rows (cells, 1-based line number).
struct table {
    std::vector<std::string> header;
    std::vector<std::pair<std::vector<std::string>, int>> rows;
};

// The cells of a table line "| a | b |", split at '|' not escaped as "\|".
std::vector<std::string> cells_of(const std::string &line) {
    std::vector<std::string> cells;
    std::string cell;
    const std::string t = trimmed(line);
    for (std::size_t i = 1; i < t.size(); ++i) {
        if (t[i] == '|' && t[i - 1] != '\\') {
            cells.push_back(trimmed(cell));
            cell.clear();
        } else {
            cell += t[i];
        }
    }
    return cells;
}

// Every table of the text whose header's first cell is `first` (normally one).
std::vector<table> tables_headed(const std::vector<std::string> &lines, const std::string &first) {
    std::vector<table> found;
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        if (trimmed(lines[i]).rfind('|', 0) != 0 || trimmed(lines[i + 1]).rfind("|---", 0) != 0) continue;
        table t;
        t.header = cells_of(lines[i]);
        if (t.header.empty() || t.header.front() != first) continue;
        for (std::size_t k = i + 2; k < lines.size() && trimmed(lines[k]).rfind('|', 0) == 0; ++k)
            t.rows.push_back({cells_of(lines[k]), int(k + 1)});
        found.push_back(t);
    }
    return found;
}

std::string without_backticks(std::string s) {
    s.erase(std::remove(s.begin(), s.end(), '`'), s.end());
    return s;
}

// The programs a "taken by" cell names: "every program" → all; otherwise the
// comma-separated names, parenthesised remarks left out. Names that are no program are
// returned in `unknown`.
std::vector<std::string> programs_named(const std::string &cell, std::vector<std::string> &unknown) {
    std::string plain;
    int depth = 0;
    for (const char c : without_backticks(cell)) {
        if (c == '(') ++depth;
        else if (c == ')') --depth;
        else if (depth == 0) plain += c;
    }
    std::vector<std::string> named;
    std::size_t at = 0;
    while (at <= plain.size()) {
        const std::size_t end = std::min(plain.find(',', at), plain.size());
        const std::string name = trimmed(plain.substr(at, end - at));
        at = end + 1;
        if (name.empty()) continue;
        if (name == "every program") return programs();
        if (is_program(name)) named.push_back(name);
        else unknown.push_back(name);
    }
    return named;
}

// A piece of command text: a line of a fenced code block (continuation lines joined) or
// an inline code span, with the 1-based line it starts on.
struct piece {
    std::string text;
    int line;
};

std::vector<piece> code_pieces(const std::vector<std::string> &lines) {
    std::vector<piece> pieces;
    bool fenced = false;
    std::string joined;
    int joined_line = 0;
    std::string span;  // an open inline span
    int span_line = 0, span_ticks = 0;
    for (std::size_t n = 0; n < lines.size(); ++n) {
        const std::string &line = lines[n];
        if (trimmed(line).rfind("```", 0) == 0 && span_ticks == 0) {
            fenced = !fenced;
            continue;
        }
        if (fenced) {
            if (joined.empty()) joined_line = int(n + 1);
            joined += line;
            if (!joined.empty() && joined.back() == '\\') {
                joined.pop_back();
                continue;
            }
            pieces.push_back({joined, joined_line});
            joined.clear();
            continue;
        }
        for (std::size_t i = 0; i < line.size();) {
            if (line[i] != '`') {
                if (span_ticks) span += line[i];
                ++i;
                continue;
            }
            int ticks = 0;
            while (i < line.size() && line[i] == '`') ++ticks, ++i;
            if (span_ticks == 0) {
                span_ticks = ticks;
                span_line = int(n + 1);
                span.clear();
            } else if (ticks == span_ticks) {
                pieces.push_back({span, span_line});
                span_ticks = 0;
            } else {
                span += std::string(std::size_t(ticks), '`');
            }
        }
        if (span_ticks) span += ' ';
        if (span_ticks && trimmed(line).empty()) span_ticks = 0;  // a paragraph ends an unclosed span
    }
    return pieces;
}

// Where the command starting at `from` ends: a pipe, a list separator or a comment.
std::size_t command_end(const std::string &text, std::size_t from) {
    std::size_t end = text.size();
    for (const char *stop : {" | ", ";", "&&", " #"}) end = std::min(end, text.find(stop, from));
    return end;
}

// Checks that each command for a program in `pieces` uses only options it lists;
// `file` names the document in messages.
void check_commands(const std::string &file, const std::vector<piece> &pieces) {
    for (const piece &p : pieces) {
        std::vector<std::pair<std::string, std::size_t>> calls;  // program, where its arguments start
        for (std::size_t at = p.text.find("build/demo/"); at != std::string::npos;
             at = p.text.find("build/demo/", at + 1)) {
            std::size_t end = at + 11;
            while (end < p.text.size() && word_char(p.text[end])) ++end;
            const std::string name = p.text.substr(at + 11, end - at - 11);
            if (name.empty()) continue;  // build/demo/<prog>, build/demo/NAME: a placeholder
            if (std::all_of(name.begin(), name.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)) || c == '_'; }))
                continue;
            CHECK_MSG(is_program(name), file + ":" + std::to_string(p.line) + ": build/demo/" + name +
                                            " is no program (demo/" + name + ".cpp does not exist)");
            if (is_program(name)) calls.push_back({name, end});
        }
        const std::string text = trimmed(p.text);
        const std::size_t first_end = std::min(text.find(' '), text.size());
        if (is_program(text.substr(0, first_end))) calls.push_back({text.substr(0, first_end), p.text.find(text) + first_end});
        for (const auto &[program, from] : calls) {
            const std::string args = p.text.substr(from, command_end(p.text, from) - from);
            for (const token &t : option_tokens(args))
                CHECK_MSG(takes(program, t.text), file + ":" + std::to_string(p.line) + ": " + program + " " + t.text +
                                                      ": " + program + " --help lists no " + t.text);
        }
    }
}

}  // namespace

TEST(readme_names_only_options_some_program_takes) {
    if (!ready("README.md")) return;
    const std::vector<std::string> lines = lines_of(file_bytes("README.md"));
    for (std::size_t n = 0; n < lines.size(); ++n) {
        for (const token &t : option_tokens(lines[n])) {
            bool known = std::any_of(programs().begin(), programs().end(), [&](const std::string &p) { return takes(p, t.text); });
            for (const auto &[option, tool] : foreign_options)
                known = known || (option == t.text && lines[n].find(tool) != std::string::npos);
            CHECK_MSG(known, "README.md:" + std::to_string(n + 1) + ": " + t.text + " is listed by no program's --help");
        }
    }
}

TEST(readme_names_only_programs_that_exist_and_every_program_has_a_demos_row) {
    if (!ready("README.md")) return;
    const std::string readme = file_bytes("README.md");
    const std::vector<std::string> lines = lines_of(readme);
    for (std::size_t n = 0; n < lines.size(); ++n) {
        for (std::size_t at = lines[n].find("build/demo/"); at != std::string::npos; at = lines[n].find("build/demo/", at + 1)) {
            std::size_t end = at + 11;
            while (end < lines[n].size() && word_char(lines[n][end])) ++end;
            const std::string name = lines[n].substr(at + 11, end - at - 11);
            if (name.empty()) continue;
            CHECK_MSG(is_program(name), "README.md:" + std::to_string(n + 1) + ": build/demo/" + name + " is no program");
        }
    }
    const std::vector<table> demos = tables_headed(lines, "demo");
    CHECK_MSG(demos.size() == 1, "README.md should have one table whose first column is 'demo', has " +
                                     std::to_string(demos.size()));
    std::set<std::string> rows;
    for (const table &t : demos) {
        for (const auto &[cells, line] : t.rows) {
            const std::string name = trimmed(without_backticks(cells.empty() ? "" : cells.front()));
            CHECK_MSG(is_program(name), "README.md:" + std::to_string(line) + ": the demos table names '" + name +
                                            "', which is no program (no demo/" + name + ".cpp)");
            rows.insert(name);
        }
    }
    for (const std::string &p : programs())
        CHECK_MSG(rows.count(p) != 0, "README.md: the demos table has no row for " + p);
    for (const table &t : tables_headed(lines, "option")) {
        for (const auto &[cells, line] : t.rows) {
            std::vector<std::string> unknown;
            programs_named(cells.empty() ? "" : cells.back(), unknown);
            for (const std::string &u : unknown)
                CHECK_MSG(false, "README.md:" + std::to_string(line) + ": the options table names '" + u +
                                     "', which is no program (write program names, or 'every program')");
        }
    }
}

TEST(readme_options_table_agrees_with_each_programs_help) {
    if (!ready("README.md")) return;
    const std::vector<table> tables = tables_headed(lines_of(file_bytes("README.md")), "option");
    CHECK_MSG(tables.size() == 1, "README.md should have one table whose first column is 'option', has " +
                                      std::to_string(tables.size()));
    for (const table &t : tables) {
        CHECK_MSG(!t.header.empty() && t.header.back() == "taken by", "README.md: the options table's last column is not 'taken by'");
        for (const auto &[cells, line] : t.rows) {
            if (cells.size() < 2) continue;
            std::vector<std::string> unknown;
            const std::vector<std::string> named = programs_named(cells.back(), unknown);
            const std::string where = "README.md:" + std::to_string(line) + ": ";
            const std::vector<token> options = option_tokens(cells.front());
            CHECK_MSG(!options.empty(), where + "an options table row without an option");
            for (const token &o : options) {
                for (const std::string &p : programs()) {
                    const bool listed = std::find(named.begin(), named.end(), p) != named.end();
                    if (listed)
                        CHECK_MSG(takes(p, o.text), where + "the table says " + p + " takes " + o.text + "; " + p +
                                                        " --help does not list it");
                    else
                        CHECK_MSG(!takes(p, o.text), where + p + " --help lists " + o.text +
                                                         ", but the table's row does not name " + p);
                }
            }
        }
    }
}

TEST(every_option_a_program_lists_is_in_the_readme) {
    if (!ready("README.md")) return;
    std::set<std::string> named;
    for (const token &t : option_tokens(file_bytes("README.md"))) named.insert(t.text);
    for (const std::string &p : programs())
        for (const std::string &o : help_options().at(p))
            CHECK_MSG(named.count(o) != 0, p + " --help lists " + o + ", which README.md does not mention");
}

TEST(commands_in_readme_and_documentation_use_their_programs_options) {
    if (!ready("README.md")) return;
    check_commands("README.md", code_pieces(lines_of(file_bytes("README.md"))));
    std::vector<fs::path> docs;
    std::error_code ec;
    for (const auto &e : fs::directory_iterator("documentation", ec))
        if (e.is_regular_file() && e.path().extension() == ".md") docs.push_back(e.path());
    std::sort(docs.begin(), docs.end());
    CHECK_MSG(!docs.empty(), "no documentation/*.md found");
    for (const fs::path &d : docs) check_commands(d.string(), code_pieces(lines_of(file_bytes(d))));
}

TEST(the_scanners_find_what_they_should) {
    // The parsing the checks above rely on, on fixed text (so a check cannot pass by
    // finding nothing).
    const std::vector<token> t = option_tokens("`--out DIR`, --size=64x64, --NAME, a--b, ---x, --x-, -h, --a1-b");
    std::vector<std::string> texts;
    for (const token &k : t) texts.push_back(k.text);
    CHECK_EQ(texts.size(), std::size_t{4});
    if (texts.size() == 4) {
        CHECK_EQ(texts[0], std::string("--out"));
        CHECK_EQ(texts[1], std::string("--size"));
        CHECK_EQ(texts[2], std::string("--x"));
        CHECK_EQ(texts[3], std::string("--a1-b"));
    }
    const std::vector<std::string> cells = cells_of("| `--lines a\\|b` | the line | wireframe, render |");
    CHECK_EQ(cells.size(), std::size_t{3});
    if (cells.size() == 3) CHECK_EQ(cells[0], std::string("`--lines a\\|b`"));
    const std::vector<piece> pieces =
        code_pieces({"text `cube --frames 0:1` and `x`", "```sh", "build/demo/render a.ply \\", "  --info  # --not", "```"});
    CHECK_EQ(pieces.size(), std::size_t{3});
    if (pieces.size() == 3) {
        CHECK_EQ(pieces[0].text, std::string("cube --frames 0:1"));
        CHECK_EQ(pieces[2].text, std::string("build/demo/render a.ply   --info  # --not"));
        CHECK_EQ(pieces[2].line, 3);
    }
    CHECK_EQ(command_end("a --b | c --d", 0), std::size_t{5});
}
