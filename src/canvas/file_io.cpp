// file_io.cpp — atomic file writing (atomic_file, write_file_atomic) and PNM output.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <new>
#include <string>
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

// What a non-regular file is, for the message.
const char *special_kind(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISBLK(mode)) return "a block device";
    return "not a regular file";
}

// Names "<path>.tmp", "<path>.tmp-1", … are tried before a random one: a save killed
// half-way leaves one of these, and the next save of the same path finds it at once.
constexpr int kNamedTemporaries = 8;

// Whether the entry `name` is what a killed save of this process's user left (and is now
// removed): a plain file with no other link, owned by us, whose flock no live save holds.
// Anything else found there (a hard or symbolic link to a file elsewhere, a folder, a
// FIFO, a live save's temporary) is left exactly as it is.
bool remove_if_abandoned(const std::string &name) {
    struct stat seen {};
    if (::lstat(name.c_str(), &seen) != 0 || !S_ISREG(seen.st_mode) || seen.st_nlink != 1 ||
        seen.st_uid != ::geteuid())
        return false;
    const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return false;
    struct stat opened {};
    const bool abandoned = ::fstat(fd, &opened) == 0 && opened.st_ino == seen.st_ino &&
                           opened.st_dev == seen.st_dev && opened.st_nlink == 1 &&
                           ::flock(fd, LOCK_EX | LOCK_NB) == 0;
    // Unlinked while locked: a save starting meanwhile cannot take the name before it is gone.
    const bool removed = abandoned && ::unlink(name.c_str()) == 0;
    ::close(fd);
    return removed;
}

// Creates the temporary of a save of `path` fresh: exclusive create (O_CREAT | O_EXCL,
// which also refuses to follow a symlink there), so an existing file is never opened,
// truncated or written. The new file is flocked until the save ends (the kernel drops the
// lock if the process dies), which tells the next save that it was abandoned. Returns the
// descriptor (−1 with errno set) and the name in `tmp`.
int create_temporary(const std::string &path, std::string &tmp) {
    for (int k = 0; k < kNamedTemporaries; ++k) {
        tmp = path + ".tmp" + (k == 0 ? std::string() : "-" + std::to_string(k));
        for (int attempt = 0; attempt < 2; ++attempt) {
            const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NONBLOCK, 0600);
            if (fd >= 0) {
                if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return fd;
                ::close(fd);  // (another save judged it abandoned in between: not ours to use)
                break;
            }
            if (errno != EEXIST) return -1;  // the folder's own reason (permission, disk full, …)
            if (!remove_if_abandoned(tmp)) break;
        }
    }
    tmp = path + ".tmp-XXXXXX";
    std::vector<char> name(tmp.begin(), tmp.end());
    name.push_back('\0');
    const int unique = ::mkostemp(name.data(), O_CLOEXEC);
    tmp.assign(name.data());
    if (unique >= 0) (void)::flock(unique, LOCK_EX | LOCK_NB);
    return unique;
}

std::string folder_of(const std::string &path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

}  // namespace

result<atomic_file> atomic_file::open(const std::string &path) {
    // (A lambda: the member's access to the private constructor, and one place to turn
    // memory that runs out while making names and messages into an error.)
    auto open_file = [&]() -> result<atomic_file> {
            if (path.empty()) return error{"", 0, -1, "cannot save: empty file name"};
            atomic_file f;
            f.path_ = path;
            struct stat st {};
            const bool exists = ::stat(path.c_str(), &st) == 0;
            if (exists && S_ISDIR(st.st_mode)) return error{path, 0, -1, "cannot save: the path is a folder"};
            if (exists && S_ISCHR(st.st_mode)) {
                // A character device (e.g. /dev/null, /dev/full): written in place, never replaced.
                // Non-blocking open, then checked again: the name may have changed since the stat.
                f.fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
                if (f.fd_ < 0) return io_error(path, "cannot open for writing", errno);
                struct stat opened {};
                if (::fstat(f.fd_, &opened) != 0 || !S_ISCHR(opened.st_mode))
                    return error{path, 0, -1, "cannot save: the path changed while being opened"};
                const int flags = ::fcntl(f.fd_, F_GETFL);
                if (flags >= 0) (void)::fcntl(f.fd_, F_SETFL, flags & ~O_NONBLOCK);
                return f;
            }
            if (exists && !S_ISREG(st.st_mode))  // a FIFO would block the save until someone reads it
                return error{path, 0, -1, std::string("cannot save: the path is ") + special_kind(st.st_mode) +
                                              ", not a regular file"};
            const std::string folder = folder_of(path);
            struct stat dst {};
            if (::stat(folder.c_str(), &dst) != 0) return io_error(path, "cannot save: folder '" + folder + "'", errno);
            if (!S_ISDIR(dst.st_mode)) return error{path, 0, -1, "cannot save: '" + folder + "' is not a folder"};
            f.fd_ = create_temporary(path, f.temporary_);
            if (f.fd_ < 0) {
                const int err = errno;
                f.temporary_.clear();
                return io_error(path, "cannot create a temporary file in '" + folder + "'", err);
            }
            return f;
    };
    try {
        return open_file();
    } catch (const std::bad_alloc &) {
        return error{path, 0, -1, "cannot save: out of memory"};
    }
}

atomic_file::atomic_file(atomic_file &&other) noexcept
    : path_(std::move(other.path_)), temporary_(std::move(other.temporary_)), fd_(other.fd_) {
    other.fd_ = -1;
    other.temporary_.clear();
}

atomic_file &atomic_file::operator=(atomic_file &&other) noexcept {
    if (this != &other) {
        abandon();
        path_ = std::move(other.path_);
        temporary_ = std::move(other.temporary_);
        fd_ = other.fd_;
        other.fd_ = -1;
        other.temporary_.clear();
    }
    return *this;
}

atomic_file::~atomic_file() { abandon(); }

status atomic_file::write(const void *data, std::size_t size) {
    if (fd_ < 0) return error{path_, 0, -1, "cannot write: the file is not open"};
    int err = 0;
    if (write_all(fd_, static_cast<const unsigned char *>(data), size, err)) return {};
    abandon();
    return io_error(path_, "write failed", err);
}

status atomic_file::commit() {
    if (fd_ < 0) return error{path_, 0, -1, "cannot save: the file is not open"};
    const bool replacing = !temporary_.empty();
    int err = 0;
    if (replacing) {
        if (::fchmod(fd_, 0644) != 0) err = errno;
        if (!err && ::fsync(fd_) != 0) err = errno;
        // Renamed before the close drops the lock: until then the name is ours. The rename
        // is the only step that touches the destination (it replaces whatever entry is
        // there, a FIFO included, without opening it).
        if (!err && ::rename(temporary_.c_str(), path_.c_str()) != 0) err = errno;
        if (err) {
            abandon();
            return io_error(path_, "cannot save", err);
        }
        temporary_.clear();
    }
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) return io_error(path_, replacing ? "cannot save" : "write failed", errno);
    return {};
}

void atomic_file::abandon() {
    if (!temporary_.empty()) ::unlink(temporary_.c_str());  // before the close drops the lock
    temporary_.clear();
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
}

status write_file_atomic(const std::string &path, const void *data, std::size_t size) {
    try {
        result<atomic_file> f = atomic_file::open(path);
        if (!f) return f.err();
        if (status s = f->write(data, size); !s) return s;
        return f->commit();
    } catch (const std::bad_alloc &) {  // (names and messages: nothing is created before them)
        return error{path, 0, -1, "cannot save: out of memory"};
    }
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
    return save_encoded(path, c, [&] { return encode_pnm(c, binary ? "P5" : "P2", 1, binary); });
}

status save_ppm(const canvas_t &c, const std::string &path, ppm_encoding encoding) {
    if (!c.data || c.width <= 0 || c.height <= 0) return error{path, 0, -1, "cannot save: invalid canvas"};
    const bool binary = encoding == ppm_encoding::binary_p6;
    return save_encoded(path, c, [&] { return encode_pnm(c, binary ? "P6" : "P3", 3, binary); });
}

}  // namespace tiny3d

bool save_canvas(const canvas_t *canvas, const char *path) {
    if (!canvas || !path) return false;
    return tiny3d::save_pgm(*canvas, path).ok();
}
