// demo_cli.h — what every demo program shares: its command line, its frame files and
// its frame timing.
//
// Every demo accepts
//   --out DIR        where frames go (created if missing; default build/frames/<demo>)
//   --frames A:B     render only frames A..B (inclusive, 0-based, global numbering: frame
//                    k is the same image whatever range it is rendered in)
//   --size WxH       canvas size (default per demo)
// plus its own options, which it takes out of `rest` with take_flag / take_value.
// Timing goes to stderr (a progress line, then min/median/max ms and fps); stdout gets
// one "wrote PATH" line per frame. Errors: a message on stderr and exit status 1.
#ifndef TINY3D_DEMO_CLI_H
#define TINY3D_DEMO_CLI_H

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "canvas.h"

namespace demo {

struct options {
    std::string name;            // demo name, for messages and the default folder
    std::string out_dir;         // --out
    int width = 0, height = 0;   // --size
    int first_frame = 0;         // --frames A:B (inclusive)
    int last_frame = 0;
    int frame_count = 0;         // the full sequence's length
    std::vector<std::string> rest;  // arguments the common parser did not take, in order
};

// Parses argv. `frame_count` is the demo's full sequence length (1 for a single image).
// Returns an error for malformed values or a range outside 0..frame_count-1.
tiny3d::result<options> parse(int argc, char **argv, const std::string &name, int default_width,
                              int default_height, int frame_count);

// Removes `flag` from rest; true if it was there.
bool take_flag(options &o, const std::string &flag);
// Removes `key VALUE` (or key=VALUE) from rest and returns VALUE.
std::optional<std::string> take_value(options &o, const std::string &key);
// Error naming the first argument nobody took (call after taking the demo's own).
tiny3d::status check_no_rest(const options &o, const std::string &usage);

// out_dir + "/" + prefix + three-digit frame number + ".pgm"
std::string frame_path(const options &o, int frame, const std::string &prefix = "frame_");

// Creates out_dir (and parents). Error on failure.
tiny3d::status prepare_out_dir(const options &o);

// Saves a frame (atomic) and prints "wrote PATH" on stdout; the error otherwise.
tiny3d::status save_frame(const canvas_t &canvas, const std::string &path);

// Per-frame wall-clock timing with a progress line on stderr.
class frame_timer {
public:
    explicit frame_timer(std::string name, int total) : name_(std::move(name)), total_(total) {}
    void start();
    void stop();        // records one frame, updates the progress line
    void report() const;  // min / median / max ms and fps on stderr
    const std::vector<double> &milliseconds() const { return ms_; }

private:
    std::string name_;
    int total_;
    std::chrono::steady_clock::time_point t0_{};
    std::vector<double> ms_;
};

// Prints "<demo>: <message>" on stderr and returns 1, for `return fail(...)` in main.
int fail(const options &o, const std::string &message);
int fail(const std::string &demo_name, const std::string &message);

}  // namespace demo

#endif
