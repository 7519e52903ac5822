// demo_cli.h — the one command-line contract of every libtiny3d program (the demos, render,
// ply_render): how options are declared, parsed and explained, where frames go, and how
// progress and timing are shown.
//
// The contract (README.md, "Programs and options", lists which program takes which option):
//  * `--help` (or -h) prints the usage, the program's description and every option with its
//    default on stdout and exits 0, whatever else is on the line.
//  * Options are `--name VALUE` or `--name=VALUE`, in any order, mixed with the positional
//    arguments; `--` ends the options. A flag given twice is the flag; a value option given
//    twice keeps the last value, except repeatable ones (e.g. render's --light), which
//    collect every value.
//  * Numbers are parsed strictly: the whole text must be the number ("3x", "", " 3", "nan",
//    "inf", "1e999" and anything outside the option's stated range are refused).
//  * A bad command line (unknown option, missing or malformed value, missing positional
//    argument) prints "<program>: <message naming the option and the value>" and a hint to
//    --help on stderr and exits with status 2 BEFORE anything is created or written.
//    Failures while running (a file that does not load, a frame that cannot be saved) exit
//    with status 1.
//  * Output: one "wrote PATH" line per file on stdout. When stdout is a terminal the lines
//    are replaced by one progress line redrawn with carriage returns ("cube: frame 12/60
//    3.2 ms  wrote …"); otherwise (a pipe, a file, `make demo`'s log) they are plain lines.
//    At the end a time summary goes to stderr: frame count, total seconds, min / median /
//    max ms per frame and the matching frames per second.
#ifndef TINY3D_DEMO_CLI_H
#define TINY3D_DEMO_CLI_H

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "animation.h"
#include "canvas.h"
#include "math3d.h"
#include "raster.h"
#include "tiny3d_result.h"
#include "wireframe.h"

namespace demo {

// Exit statuses.
inline constexpr int EXIT_USAGE = 2;    // bad command line; nothing was written
inline constexpr int EXIT_FAILURE_RUN = 1;  // a failure while running

// Strict parsers (the whole text must match); each returns an error message naming
// `option` and the text, or "" on success.
std::string parse_int(const std::string &option, const std::string &text, long min, long max, long &out);
std::string parse_number(const std::string &option, const std::string &text, double min, double max, double &out);
// "X,Y,Z": three finite numbers separated by commas.
std::string parse_vec3(const std::string &option, const std::string &text, vec3_t &out);

// What the common options hold after parsing (only those a program declared are set).
struct common_options {
    std::string out_dir;            // --out DIR
    int width = 0, height = 0;      // --size WxH
    int first_frame = 0;            // --frames A:B (inclusive, global numbering)
    int last_frame = 0;
    int frame_count = 1;            // the full sequence's length
    int threads = 1;                // --threads N
    bool png = false;               // --png: a PNG beside every PGM
    tiny3d::sample_count samples = tiny3d::sample_count::x1;  // --aa N: filled triangles' samples per pixel
    std::string gif_path;           // --gif FILE: the frames rendered, as one animated GIF
    double fps = 30.0;              // --fps X: the sequence's frame rate (frame k at k / fps s)
    bool out_given = false;         // --out was on the command line
    int frames_to_render() const { return last_frame - first_frame + 1; }
    // PGM (and PNG) frames are written unless only a GIF was asked for (--gif without --out).
    bool write_frames() const { return gif_path.empty() || out_given; }
};

// A program's command line: declare the options, then parse().
class command_line {
public:
    // `name` is the program's name (messages, the default output folder build/frames/<name>);
    // `synopsis` the positional part of the usage line ("FILE.obj|FILE.ply"), may be empty;
    // `description` a paragraph printed by --help.
    command_line(std::string name, std::string synopsis, std::string description);

    const std::string &name() const { return name_; }
    common_options common;

    // ---- the common options (declare those that make sense for the program) ----
    void add_out();                                    // default build/frames/<name>
    void add_size(int default_width, int default_height);
    // --frames A:B over a sequence of frame_count frames (default: all of them). When the
    // length depends on other options, pass a function: it is called once every option has
    // been parsed, and the range is checked against its value.
    void add_frames(std::function<int()> frame_count);
    void add_threads(int default_threads);
    void add_png();
    // --aa 1|4|8|16: samples per pixel of the filled triangles (render_context::begin_frame).
    void add_samples(tiny3d::sample_count default_samples);
    // --gif FILE and --fps X (0.1..1000, default 30; with --gif at most 50, GIF's limit):
    // the frames rendered also go into one animated GIF played at X frames per second
    // (tiny3d::gif_writer), and the PGM/PNG frames only when --out is given too.
    void add_gif();
    // What a program writing a sequence of frames takes: --out, --frames, --size, --png,
    // --gif, --fps.
    void add_sequence_options(int frame_count, int default_width, int default_height);
    void add_sequence_options(std::function<int()> frame_count, int default_width, int default_height);

    // ---- a program's own options ----
    void flag(const std::string &name, bool &target, const std::string &help);
    void integer(const std::string &name, int &target, int min, int max, const std::string &help);
    void number(const std::string &name, double &target, double min, double max, const std::string &help);
    void number(const std::string &name, float &target, float min, float max, const std::string &help);
    void choice(const std::string &name, std::string &target, std::vector<std::string> choices,
                const std::string &help);
    void text(const std::string &name, const std::string &metavar, std::string &target, const std::string &help);
    void vector3(const std::string &name, vec3_t &target, bool &given, const std::string &help);
    // Repeatable: every occurrence appends.
    void vector3_list(const std::string &name, std::vector<vec3_t> &target, const std::string &help);
    // Any option with its own parser: `set` returns "" or an error message.
    void custom(const std::string &name, const std::string &metavar, const std::string &help,
                std::function<std::string(const std::string &)> set, bool repeatable = false);

    // Positional arguments in order; required ones must come before optional ones.
    void positional(const std::string &metavar, std::string &target, bool required);

    // Parses argv. Returns -1 when the program should run, otherwise the exit status it
    // should return at once: 0 after --help (usage printed on stdout), EXIT_USAGE after a
    // bad command line (message on stderr).
    int parse(int argc, char **argv);

    // The --help text.
    std::string help() const;
    // "<program>: <message>" (+ a hint to --help) on stderr; returns EXIT_USAGE. For checks
    // between options that parse() cannot make.
    int usage_error(const std::string &message) const;
    // "<program>: <message>" on stderr; returns EXIT_FAILURE_RUN.
    int fail(const std::string &message) const;

private:
    struct option {
        std::string name, metavar, help;
        bool takes_value = true;
        bool repeatable = false;
        std::function<std::string(const std::string &)> set;
    };
    struct positional_arg {
        std::string metavar;
        std::string *target;
        bool required;
    };
    option *find(const std::string &name);
    void add(option o);

    std::string name_, synopsis_, description_;
    std::vector<option> options_;
    std::vector<positional_arg> positionals_;
    std::function<int()> frame_count_;  // set by add_frames
    std::string frames_text_;           // the --frames value, checked at the end of parse()
};

// Creates the output folder (and parents). Error on failure.
tiny3d::status prepare_out_dir(const common_options &o);

// out_dir + "/" + prefix + three-digit frame number + ".pgm"
std::string frame_path(const common_options &o, int frame, const std::string &prefix = "frame_");

// Per-frame timing, the "wrote" lines / progress line and the closing summary.
class progress {
public:
    // `total` = frames the program renders; writes go to stdout, the summary to stderr.
    progress(std::string name, int total);
    // A sequence's progress: o.frames_to_render() frames, and save() writes what `o` asks
    // for (PGM/PNG frames, the GIF of --gif).
    progress(std::string name, const common_options &o);
    void start();  // a frame begins
    void stop();   // the frame's pixels are done (its time is recorded)
    // Saves canvas as PGM at `pgm_path` (and, with `png`, as PNG beside it: the same name
    // ending in .png), atomically, and reports each file written. Made from common_options:
    // the PGM/PNG only when o.write_frames(), and the canvas appended to the --gif file.
    tiny3d::status save(const canvas_t &canvas, const std::string &pgm_path, bool png);
    void report_written(const std::string &path);
    // Finishes the --gif file (renamed into place now; an error leaves no file), ends the
    // progress line and prints the summary (nothing when no frame was timed).
    tiny3d::status finish();
    const tiny3d::frame_clock &clock() const { return clock_; }  // the render time of each frame

private:
    std::string name_;
    int total_;
    bool terminal_;
    bool line_open_ = false;
    double began_s_, frame_began_s_ = 0.0;
    tiny3d::frame_clock clock_;
    bool write_frames_ = true;
    std::string gif_path_;
    tiny3d::gif_options gif_options_;
    std::optional<tiny3d::gif_writer> gif_;  // opened by the first save()
};

// The line drawer named by a --lines choice: "tabulated", "faithful", anything else the
// exact coverage line (the parser has already restricted the value to the choices).
tiny3d::line_method line_method_named(const std::string &name);

}  // namespace demo

#endif
