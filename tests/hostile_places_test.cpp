// hostile_places_test.cpp — `render` in hostile places and at the machine's limits
// (documentation/reliability.md, "Hostile places"): a FIFO where a frame goes, a hard link
// at the temporary's name, threads the system refuses, an address-space limit, a flat
// mesh turning edge-on, control bytes in a PNM header, a mesh through a pipe. Each case
// runs the real program in a child process and checks its exit code, its message, and
// that nothing outside the output folder changed (every entry of the test's folder but
// the output folder compared before and after: kind, bytes, link count, inode).
//
// Children get an alarm (kept across exec): a run that blocks is killed by SIGALRM and
// the test fails instead of hanging.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"
#include "tiny3d.h"

namespace fs = std::filesystem;
using program_runner::file_bytes;
using program_runner::temp_dir;

namespace {

constexpr unsigned kChildSeconds = 120;  // far beyond any case's run: only a hang reaches it

struct child_run {
    int exit_code = -1;  // -1: killed by a signal (signal in `signal`)
    int signal = 0;
    std::string out, err;
};

// Runs `args` (args[0] the program) in a child: `setup` runs in the child first (limits,
// user), stdin from `input` (a file path; /dev/null if empty), stdout and stderr captured.
child_run run_child(const std::vector<std::string> &args, const fs::path &logs,
                    const std::function<void()> &setup = {}, const std::string &input = "") {
    const std::string out_file = (logs / "child.out").string(), err_file = (logs / "child.err").string();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int in = ::open(input.empty() ? "/dev/null" : input.c_str(), O_RDONLY);
        const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
        const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
        if (in < 0 || out < 0 || err < 0) ::_exit(126);
        ::dup2(in, 0), ::dup2(out, 1), ::dup2(err, 2);
        if (setup) setup();
        const rlimit no_core{0, 0};
        ::setrlimit(RLIMIT_CORE, &no_core);
        ::alarm(kChildSeconds);
        std::vector<char *> argv;
        for (const std::string &a : args) argv.push_back(const_cast<char *>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    child_run r;
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    r.out = file_bytes(out_file);
    r.err = file_bytes(err_file);
    return r;
}

// Every entry under `root` except those under `skip`: relative path → kind, link count,
// inode and (for plain files) bytes.
std::map<std::string, std::string> snapshot(const fs::path &root, const fs::path &skip) {
    std::map<std::string, std::string> seen;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path p = it->path();
        if (p == skip) {
            it.disable_recursion_pending();
            continue;
        }
        struct stat st {};
        ::lstat(p.c_str(), &st);
        std::string what = std::to_string(st.st_mode) + "/" + std::to_string(st.st_nlink) + "/" +
                           std::to_string(st.st_ino) + "/";
        if (S_ISREG(st.st_mode)) what += file_bytes(p);
        seen[fs::relative(p, root).string()] = what;
    }
    return seen;
}

bool says(const child_run &r, const std::string &words) { return r.err.find(words) != std::string::npos; }

std::string render_path() { return fs::absolute(program_runner::demo_path("render")).string(); }

// A 1×1 quad in the z = 0 plane: flat, so edge-on twice per turn.
const char *kQuad = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";

// A folder for one case: `work` (inputs and things outside the output), `work/out`.
struct scene {
    temp_dir root, logs;  // (the children's captured output goes to logs, outside the compared folder)
    fs::path out, mesh;
    scene() : out(root.path / "out"), mesh(root.path / "quad.obj") {
        fs::create_directory(out);
        std::FILE *f = std::fopen(mesh.c_str(), "wb");
        std::fputs(kQuad, f);
        std::fclose(f);
    }
    std::vector<std::string> render(std::vector<std::string> extra) const {
        std::vector<std::string> args = {render_path(), mesh.string(), "--out", out.string(), "--size", "48x36",
                                         "--cull", "none"};
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    }
};

}  // namespace

// 1. A FIFO at a frame's path: refused at once with a message (no reader ever comes).
TEST(a_fifo_where_a_frame_goes_is_refused_not_waited_on) {
    scene s;
    const fs::path fifo = s.out / "frame_000.pgm";
    CHECK(::mkfifo(fifo.c_str(), 0600) == 0);
    const auto before = snapshot(s.root.path, s.out);
    const child_run r = run_child(s.render({"--turntable", "1"}), s.logs.path);
    CHECK_EQ(r.signal, 0);
    CHECK_EQ(r.exit_code, 1);
    CHECK_MSG(says(r, fifo.string() + ": cannot save: the path is a FIFO (named pipe), not a regular file"), r.err);
    struct stat st {};
    CHECK(::lstat(fifo.c_str(), &st) == 0 && S_ISFIFO(st.st_mode));  // still the FIFO
    CHECK_EQ(program_runner::files_in(s.out).size(), std::size_t(0));  // and no temporary left
    CHECK(snapshot(s.root.path, s.out) == before);
}

// 2. Hard links to a file outside the output folder at the temporary's names: the save
// creates its own temporary, the linked file keeps its bytes and its links.
TEST(a_hard_link_at_the_temporarys_name_is_never_written_through) {
    scene s;
    const fs::path precious = s.root.path / "precious.txt";
    std::FILE *f = std::fopen(precious.c_str(), "wb");
    std::fputs("keep me", f);
    std::fclose(f);
    CHECK(::link(precious.c_str(), (s.out / "frame_000.pgm.tmp").c_str()) == 0);
    CHECK(::link(precious.c_str(), (s.out / "frame_000.pgm.tmp-1").c_str()) == 0);
    const auto before = snapshot(s.root.path, s.out);
    const child_run r = run_child(s.render({"--turntable", "1"}), s.logs.path);
    CHECK_EQ(r.exit_code, 0);
    CHECK(snapshot(s.root.path, s.out) == before);  // precious: same bytes, inode, 3 links
    CHECK(file_bytes(precious) == "keep me");
    const auto files = program_runner::files_in(s.out);
    CHECK_EQ(files.size(), std::size_t(3));  // the frame and the two links, nothing else
    CHECK(program_runner::parse_pgm(files.at("frame_000.pgm")).width == 48);
    CHECK(files.at("frame_000.pgm.tmp") == "keep me" && files.at("frame_000.pgm.tmp-1") == "keep me");
}

// 3. Threads the system refuses: RLIMIT_NPROC = 1 (the child itself). The limit does not
// bind root (CAP_SYS_RESOURCE), so a root test first becomes `nobody` in the child, the
// way `ulimit -u 1` binds an ordinary user; the folder is opened to it. The run goes on
// one thread, says so, and draws the same image as --threads 1.
TEST(threads_the_system_refuses_mean_fewer_threads_and_a_warning) {
    scene s;
    fs::permissions(s.root.path, fs::perms::all);
    fs::permissions(s.out, fs::perms::all);
    const child_run one = run_child(s.render({"--turntable", "1", "--threads", "1"}), s.logs.path);
    CHECK_EQ(one.exit_code, 0);
    const std::string single = file_bytes(s.out / "frame_000.pgm");
    fs::remove(s.out / "frame_000.pgm");
    const auto before = snapshot(s.root.path, s.out);
    const child_run r = run_child(s.render({"--turntable", "1", "--threads", "4"}), s.logs.path, [] {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(125);
        const rlimit one_process{1, 1};
        ::setrlimit(RLIMIT_NPROC, &one_process);
    });
    CHECK_EQ(r.signal, 0);
    CHECK_EQ(r.exit_code, 0);
    CHECK_MSG(says(r, "render: warning: the system refused to create threads: rendering on 1 of the 4 asked for"),
              r.err);
    CHECK(file_bytes(s.out / "frame_000.pgm") == single);
    CHECK(snapshot(s.root.path, s.out) == before);
}

// 4. Memory: a binary PLY of one triangle strip (300,000 one-byte indices, 256 vertices)
// under address-space limits from too small to load it to enough to render it. Every run
// either renders or fails with a message naming the file and what did not fit; none is
// killed (std::bad_alloc escaping would abort).
TEST(memory_running_out_is_an_error_naming_the_input_never_an_abort) {
    scene s;
    const int indices = 300000, vertices = 256;
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1\n"
                      "property list int uchar vertex_indices\nend_header\n";
    for (int i = 0; i < vertices; ++i) {
        const float xyz[3] = {float(i / 2) / 64.0f - 1.0f, float(i % 2) * 0.5f, float(i % 11) * 0.01f};
        ply.append(reinterpret_cast<const char *>(xyz), sizeof xyz);
    }
    const std::int32_t count = indices;
    ply.append(reinterpret_cast<const char *>(&count), 4);
    for (int i = 0; i < indices; ++i) ply += char(i % 256);
    const fs::path strip = s.root.path / "strip.ply";
    std::FILE *f = std::fopen(strip.c_str(), "wb");
    std::fwrite(ply.data(), 1, ply.size(), f);
    std::fclose(f);
    const auto before = snapshot(s.root.path, s.out);
    int failed = 0, rendered = 0;
    for (long megabytes = 24; megabytes <= 64; megabytes += 4) {
        const child_run r = run_child(
            {render_path(), strip.string(), "--out", s.out.string(), "--size", "64x48", "--turntable", "1"},
            s.logs.path, [megabytes] {
                const rlimit space{rlim_t(megabytes) << 20, rlim_t(megabytes) << 20};
                ::setrlimit(RLIMIT_AS, &space);
            });
        CHECK_MSG(r.signal == 0, std::to_string(megabytes) + " MB: killed by signal " + std::to_string(r.signal));
        CHECK_MSG(r.exit_code == 0 || (r.exit_code == 1 && says(r, strip.string()) && says(r, "out of memory")),
                  std::to_string(megabytes) + " MB: " + r.err);
        failed += r.exit_code == 1;
        rendered += r.exit_code == 0;
    }
    CHECK(failed > 0);
    CHECK(rendered > 0);
    CHECK(snapshot(s.root.path, s.out) == before);
}

// 5. The default turntable of a flat quad: frames 9 and 27 of 36 see it edge-on and show
// only the background. They are written and warned about; the run succeeds. A camera
// that sees nothing in any frame fails the run.
TEST(a_flat_mesh_turns_edge_on_with_a_warning_and_a_view_of_nothing_fails) {
    scene s;
    const auto before = snapshot(s.root.path, s.out);
    const child_run r = run_child(s.render({}), s.logs.path);
    CHECK_EQ(r.exit_code, 0);
    CHECK_EQ(program_runner::files_in(s.out).size(), std::size_t(36));
    const std::string mesh = s.mesh.string();
    CHECK_MSG(says(r, "render: warning: " + mesh + ": frame 9 shows nothing but the background"), r.err);
    CHECK_MSG(says(r, "render: warning: " + mesh + ": frame 27 shows nothing but the background"), r.err);
    CHECK(!says(r, "frame 8 shows") && !says(r, "frame 10 shows"));
    // Frame 9 really is blank (every pixel the background, 0.04 → 10) and frame 0 is not.
    const auto frame9 = program_runner::parse_pgm(file_bytes(s.out / "frame_009.pgm"));
    const auto frame0 = program_runner::parse_pgm(file_bytes(s.out / "frame_000.pgm"));
    CHECK(frame9.width == 48 && frame0.width == 48);
    int lit9 = 0, lit0 = 0;
    for (std::size_t i = 0; i < frame9.pixels.size(); ++i) lit9 += frame9.pixels[i] != 10, lit0 += frame0.pixels[i] != 10;
    CHECK_EQ(lit9, 0);
    CHECK(lit0 > 100);
    // Looking away from the mesh in every frame: the run fails after them.
    const child_run away = run_child(s.render({"--turntable", "2", "--eye", "0,0,5", "--target", "0,0,10"}), s.logs.path);
    CHECK_EQ(away.exit_code, 1);
    CHECK_MSG(says(away, mesh + ": no frame shows anything but the background"), away.err);
    CHECK(snapshot(s.root.path, s.out) == before);
}

// 6. Control bytes in a PNM header are shown in hex as C writes them.
TEST(bytes_in_pnm_header_messages_are_in_hex) {
    scene s;
    const fs::path esc = s.root.path / "esc.pgm", high = s.root.path / "high.pgm";
    for (const auto &[path, bytes] : {std::pair{esc, std::string("P5\n\x1b 4\n255\n")},
                                      std::pair{high, std::string("P5\n4 4\n2\x86" "5\n")}}) {
        std::FILE *f = std::fopen(path.c_str(), "wb");
        std::fwrite(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
    }
    const auto before = snapshot(s.root.path, s.out);
    const child_run a = run_child(s.render({"--turntable", "1", "--texture", esc.string()}), s.logs.path);
    CHECK_EQ(a.exit_code, 1);
    CHECK_MSG(says(a, esc.string() + ":2: expected width, found '\\x1b'"), a.err);
    const child_run b = run_child(s.render({"--turntable", "1", "--texture", high.string()}), s.logs.path);
    CHECK_EQ(b.exit_code, 1);
    CHECK_MSG(says(b, "'\\x86'"), b.err);
    CHECK(snapshot(s.root.path, s.out) == before);
}

// 7. A mesh of unknown size: through a pipe as "-" (format given, or detected from the
// content), as /dev/stdin, and from a name without a telling extension. Each gives the
// frame the file itself gives.
TEST(a_mesh_through_a_pipe_is_read_to_the_end_of_the_stream) {
    scene s;
    const child_run file = run_child(s.render({"--turntable", "1"}), s.logs.path);
    CHECK_EQ(file.exit_code, 0);
    const std::string expected = file_bytes(s.out / "frame_000.pgm");
    CHECK(!expected.empty());
    const auto before = snapshot(s.root.path, s.out);
    const std::string pipe_in = "cat " + program_runner::shell_quoted(s.mesh.string()) + " | ";
    const std::string out = program_runner::shell_quoted(s.out.string());
    const std::vector<std::string> commands = {
        pipe_in + program_runner::shell_quoted(render_path()) + " - --format obj",
        pipe_in + program_runner::shell_quoted(render_path()) + " -",
        pipe_in + program_runner::shell_quoted(render_path()) + " /dev/stdin",
    };
    for (const std::string &c : commands) {
        fs::remove(s.out / "frame_000.pgm");
        // (In parentheses: the runner's own "</dev/null" then feeds the group, not render.)
        const auto r = program_runner::run_shell(
            "(" + c + " --out " + out + " --size 48x36 --cull none --turntable 1)", s.logs.path);
        CHECK_MSG(r.exit_code == 0, c + ": " + r.err);
        CHECK_MSG(file_bytes(s.out / "frame_000.pgm") == expected, c);
    }
    // Content that is no mesh: named as such, from standard input.
    const auto junk = program_runner::run_shell("(echo hello | " + program_runner::shell_quoted(render_path()) +
                                                    " - --out " + out + " --turntable 1)",
                                                s.logs.path);
    CHECK_EQ(junk.exit_code, 1);
    CHECK_MSG(junk.err.find("<stdin>:1: unknown mesh format") != std::string::npos, junk.err);
    CHECK(snapshot(s.root.path, s.out) == before);
    // The size limit holds for a stream as for a file.
    int fds[2];
    CHECK(::pipe(fds) == 0);
    CHECK(::write(fds[1], "0123456789", 10) == 10);
    ::close(fds[1]);
    const auto limited = tiny3d::read_file_bytes("/proc/self/fd/" + std::to_string(fds[0]), 9);
    ::close(fds[0]);
    CHECK_MSG(!limited.ok() && limited.err().reason.find("more than the 9-byte limit came through the pipe") !=
                                   std::string::npos,
              limited.message());
    // A /proc pseudo-file announces size 0 and is read whole.
    const auto status = tiny3d::read_file_bytes("/proc/self/status");
    CHECK(status.ok() && status->find("Name:") == 0);
}
