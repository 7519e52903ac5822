// file_io.cpp — atomic file writing and PGM output.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "canvas.h"

namespace tiny3d {
namespace {

error io_error(const std::string &path, const std::string &what, int err) {
    return error{path, 0, -1, what + ": " + std::strerror(err)};
}

// Writes all bytes to fd, retrying short writes and EINTR.
bool write_all(int fd, const unsigned char *p, std::size_t n, int &err) {
    while (n > 0) {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0) {
            if (errno == EINTR) continue;
            err = errno;
            return false;
        }
        p += w;
        n -= std::size_t(w);
    }
    return true;
}

// The temporary file of a save of `path`: "<path>.tmp", one name per target, so a save
// that a killed run left behind is taken over (truncated, rewritten and renamed) by the
// next save of the same file instead of staying forever. The name is claimed with an
// exclusive flock, which the kernel drops when its holder dies: a held lock means a live
// save of the same target in another process (or thread), and this save then takes a
// unique "<path>.tmp-XXXXXX" as before. After locking, the name must still be the opened
// file (the other save may have renamed it onto the target meanwhile: never truncate
// that). Returns the descriptor (−1 with errno set) and the name in `tmp`.
int open_temporary(const std::string &path, std::string &tmp) {
    tmp = path + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0600);
    if (fd >= 0) {
        struct stat opened {}, named {};
        const bool claimed = ::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::fstat(fd, &opened) == 0 &&
                             S_ISREG(opened.st_mode) && ::stat(tmp.c_str(), &named) == 0 &&
                             named.st_dev == opened.st_dev && named.st_ino == opened.st_ino &&
                             ::ftruncate(fd, 0) == 0;
        if (claimed) return fd;
        ::close(fd);  // in use by a live save (or not a plain file): a unique name instead
    }
    // Also when the name cannot be opened (a symlink, folder or FIFO there, another user's
    // file): mkstemp then fails with the folder's own reason if no file can be made.
    tmp = path + ".tmp-XXXXXX";
    std::vector<char> name(tmp.begin(), tmp.end());
    name.push_back('\0');
    const int unique = ::mkstemp(name.data());
    tmp.assign(name.data());
    return unique;
}

std::string folder_of(const std::string &path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

}  // namespace

// ---- atomic_file: the temporary, the checks and the rename of every save ----

atomic_file::atomic_file(std::string path, std::string temporary, int fd)
    : path_(std::move(path)), temporary_(std::move(temporary)), fd_(fd) {}

atomic_file::atomic_file(atomic_file &&other) noexcept
    : path_(std::move(other.path_)), temporary_(std::move(other.temporary_)), fd_(other.fd_) {
    other.fd_ = -1;
}

atomic_file &atomic_file::operator=(atomic_file &&other) noexcept {
    if (this != &other) {
        discard();
        path_ = std::move(other.path_);
        temporary_ = std::move(other.temporary_);
        fd_ = other.fd_;
        other.fd_ = -1;
    }
    return *this;
}

atomic_file::~atomic_file() { discard(); }

result<atomic_file> atomic_file::open(const std::string &path) {
    if (path.empty()) return error{"", 0, -1, "cannot save: empty file name"};
    struct stat st {};
    const bool exists = ::stat(path.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) return error{path, 0, -1, "cannot save: the path is a folder"};
    if (exists && !S_ISREG(st.st_mode)) {  // a device or FIFO (e.g. /dev/full, /dev/stdout): in place, never replaced
        const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) return io_error(path, "cannot open for writing", errno);
        return atomic_file(path, "", fd);
    }
    const std::string folder = folder_of(path);
    struct stat dst {};
    if (::stat(folder.c_str(), &dst) != 0) return io_error(path, "cannot save: folder '" + folder + "'", errno);
    if (!S_ISDIR(dst.st_mode)) return error{path, 0, -1, "cannot save: '" + folder + "' is not a folder"};
    std::string tmp;
    const int fd = open_temporary(path, tmp);
    if (fd < 0) return io_error(path, "cannot create a temporary file in '" + folder + "'", errno);
    return atomic_file(path, tmp, fd);
}

status atomic_file::write(const void *data, std::size_t size) {
    if (fd_ < 0) return error{path_, 0, -1, "cannot write: the file is closed"};
    int err = 0;
    if (write_all(fd_, static_cast<const unsigned char *>(data), size, err)) return {};
    discard();
    return io_error(path_, "write failed", err);
}

status atomic_file::commit() {
    if (fd_ < 0) return error{path_, 0, -1, "cannot save: the file is closed"};
    const int fd = fd_;
    fd_ = -1;
    int err = 0;
    bool ok = true;
    if (!temporary_.empty()) {
        if (::fchmod(fd, 0644) != 0) { err = errno; ok = false; }
        if (ok && ::fsync(fd) != 0) { err = errno; ok = false; }
        // Renamed (or removed) before the close drops the lock: until then the name is ours.
        if (ok && ::rename(temporary_.c_str(), path_.c_str()) != 0) { err = errno; ok = false; }
        if (!ok) ::unlink(temporary_.c_str());
    }
    if (::close(fd) != 0 && ok) { err = errno; ok = false; }
    if (!ok) return io_error(path_, "cannot save", err);
    return {};
}

void atomic_file::discard() {
    if (fd_ < 0) return;
    if (!temporary_.empty()) ::unlink(temporary_.c_str());  // before the close drops the lock
    ::close(fd_);
    fd_ = -1;
}

status write_file_atomic(const std::string &path, const void *data, std::size_t size) {
    result<atomic_file> file = atomic_file::open(path);
    if (!file) return file.err();
    if (status written = file->write(data, size); !written) return written;
    return file->commit();
}

namespace {

// 8-bit sample of an intensity: round(clamp(v, 0, 1)·255); NaN → 0.
unsigned to_byte(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return unsigned(std::lround(v * 255.0f));
}

// A grey canvas as a PNM file with maxval 255: `channels` copies of each sample (1 for
// PGM, 3 for PPM), binary or ASCII (at most 16 samples per text line).
std::string encode_pnm(const canvas_t &c, const char *magic, int channels, bool binary) {
    const std::size_t n = std::size_t(c.width) * std::size_t(c.height);
    std::string out = std::string(magic) + "\n" + std::to_string(c.width) + " " + std::to_string(c.height) + "\n255\n";
    if (binary) {
        const std::size_t header = out.size();
        out.resize(header + n * std::size_t(channels));
        char *dst = out.data() + header;
        for (std::size_t i = 0; i < n; ++i)
            for (int ch = 0; ch < channels; ++ch) *dst++ = char(to_byte(c.data[i]));
        return out;
    }
    out.reserve(out.size() + n * 4 * std::size_t(channels));
    for (int y = 0; y < c.height; ++y) {
        int on_line = 0;
        for (int x = 0; x < c.width; ++x)
            for (int ch = 0; ch < channels; ++ch) {
                if (on_line) out += (on_line % 16 == 0) ? '\n' : ' ';
                out += std::to_string(to_byte(c.pixels[y][x]));
                ++on_line;
            }
        out += '\n';
    }
    return out;
}

}  // namespace

status save_pgm(const canvas_t &c, const std::string &path, pgm_encoding encoding) {
    if (!c.data || c.width <= 0 || c.height <= 0) return error{path, 0, -1, "cannot save: invalid canvas"};
    const bool binary = encoding == pgm_encoding::binary_p5;
    const std::string out = encode_pnm(c, binary ? "P5" : "P2", 1, binary);
    return write_file_atomic(path, out.data(), out.size());
}

status save_ppm(const canvas_t &c, const std::string &path, ppm_encoding encoding) {
    if (!c.data || c.width <= 0 || c.height <= 0) return error{path, 0, -1, "cannot save: invalid canvas"};
    const bool binary = encoding == ppm_encoding::binary_p6;
    const std::string out = encode_pnm(c, binary ? "P6" : "P3", 3, binary);
    return write_file_atomic(path, out.data(), out.size());
}

}  // namespace tiny3d

bool save_canvas(const canvas_t *canvas, const char *path) {
    if (!canvas || !path) return false;
    return tiny3d::save_pgm(*canvas, path).ok();
}
