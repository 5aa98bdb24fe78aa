// genmesh/detail/io/common.h — machinery shared by the readers and writers:
// whole-file reading, a text cursor that counts lines, number parsing with
// std::from_chars, byte-order helpers, and the atomic file writer.
//
// Private to <genmesh/io.h>; nothing here is API.
#pragma once

#include <genmesh/attribute_traits.h>
#include <genmesh/exceptions.h>
#include <genmesh/polygon_soup.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <vector>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace genmesh::detail::io {

/// A file's whole content and its name, as the errors print it.
struct File_content {
  std::string name;
  std::string data;
};

/// The default bound on an input file's size (Read_options::max_file_size):
/// 8 GiB, far above any mesh file genmesh can hold in memory as a soup on a
/// usual machine, and low enough that a sparse or endless file is refused at
/// once rather than after filling the memory.
inline constexpr std::uint64_t default_max_file_size = std::uint64_t{8} << 30;

/// "12.3 MiB" (powers of 1024, as the CLI's size options) for messages.
inline std::string human_bytes(std::uint64_t n) {
  const char* unit[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double v = static_cast<double>(n);
  int u = 0;
  while (v >= 1024 && u < 6) {
    v /= 1024;
    ++u;
  }
  char b[48];
  if (u == 0) std::snprintf(b, sizeof b, "%llu bytes", static_cast<unsigned long long>(n));
  else std::snprintf(b, sizeof b, "%.1f %s", v, unit[u]);
  return b;
}

/// Reads the whole file; throws io_error if it is missing, unreadable, empty,
/// not a regular file, a pipe or socket that gives more than `max_size`
/// bytes, or a regular file larger than `max_size` (checked before any byte
/// is read, so a 10 GB sparse file is refused at once). Devices (/dev/zero,
/// /dev/urandom, a terminal) and directories are refused: they have no end
/// or no content. Pipes (`genmesh info /dev/stdin < x.off`, process
/// substitution) are read up to `max_size`.
inline File_content read_whole_file(const std::filesystem::path& path,
                                    std::uint64_t max_size = default_max_file_size) {
  File_content f{path.string(), {}};
  const auto refuse_special = [&](mode_t mode) {
    if (S_ISDIR(mode)) throw io_error(f.name, "is a directory, not a file");
    if (!S_ISREG(mode) && !S_ISFIFO(mode) && !S_ISSOCK(mode))
      throw io_error(f.name, std::string("is not a regular file (") +
                                 (S_ISCHR(mode) ? "a character device" : S_ISBLK(mode) ? "a block device" : "a special file") +
                                 "): genmesh reads regular files, pipes and sockets only");
  };
  // Devices are refused before open(), which could block on some of them (a
  // FIFO's open() waits for its writer, as cat does).
  struct stat pre {};
  if (::stat(f.name.c_str(), &pre) == 0) refuse_special(pre.st_mode);
  const int fd = ::open(f.name.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int err = errno;
    std::error_code ec;
    if (err == ENOENT) throw io_error(f.name, "file does not exist");
    if (std::filesystem::is_directory(path, ec)) throw io_error(f.name, "is a directory, not a file");
    throw io_error(f.name, std::string("cannot open file: ") + std::strerror(err));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw io_error(f.name, std::string("cannot stat file: ") + std::strerror(errno));
  refuse_special(st.st_mode);
  const bool regular = S_ISREG(st.st_mode);
  if (regular && static_cast<std::uint64_t>(st.st_size) > max_size)
    throw io_error(f.name, "the file is " + human_bytes(static_cast<std::uint64_t>(st.st_size)) +
                               ", larger than the limit of " + human_bytes(max_size) + " for an input file");
  std::string data;
  try {
    if (regular) data.reserve(static_cast<std::size_t>(st.st_size));
    std::size_t used = 0;
    for (;;) {
      if (data.size() - used < (1u << 16))
        data.resize(std::min<std::uint64_t>(
            std::max<std::uint64_t>(data.size() + (1u << 16), regular ? static_cast<std::uint64_t>(st.st_size) + 1 : data.size() * 2),
            max_size + (1u << 16)));
      const ssize_t n = ::read(fd, data.data() + used, data.size() - used);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw io_error(f.name, std::string("read error: ") + std::strerror(errno), std::nullopt, used);
      }
      if (n == 0) break;
      used += static_cast<std::size_t>(n);
      if (used > max_size)
        throw io_error(f.name, "more than " + human_bytes(max_size) +
                                   " read and no end in sight: larger than the limit for an input file");
    }
    data.resize(used);
  } catch (const std::bad_alloc&) {
    throw io_error(f.name, "out of memory while reading the file (" + human_bytes(data.size()) + " read)");
  }
  if (data.empty()) throw io_error(f.name, "file is empty", std::nullopt, 0);
  f.data = std::move(data);
  return f;
}

/// Printable excerpt of a token for error messages (binary bytes as \xNN).
inline std::string quote(std::string_view s, std::size_t max_len = 24) {
  std::string out = "'";
  for (std::size_t i = 0; i < s.size() && i < max_len; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static constexpr char hex[] = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (s.size() > max_len) out += "...";
  return out + "'";
}

inline bool is_text_byte(unsigned char c) {
  return c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v' || (c >= 0x20 && c != 0x7f);
}

/// Cursor over a text buffer. Lines are 1-based and end at LF, CRLF or a
/// lone CR (all three read the same: old Mac exporters write CR only, and a
/// stray CR must not glue two statements into one); whitespace within a line
/// is space, tab, \f, \v. Every error it throws names the file and the line.
class Text_cursor {
public:
  /// With `text_only`, a NUL byte anywhere after `start` is reported at once
  /// as binary data (off for headers followed by binary data, as in PLY).
  Text_cursor(const File_content& file, std::size_t start = 0, std::uint64_t line = 1,
              bool text_only = true)
      : file_(&file), p_(file.data.data() + start), end_(file.data.data() + file.data.size()),
        line_(line) {
    if (text_only) check_no_nul(start);
    if (start == 0 && file.data.starts_with("\xEF\xBB\xBF")) p_ += 3;   // UTF-8 byte order mark
    // LF-only text (the common case) keeps memchr's speed in next_line().
    has_cr_ = std::memchr(p_, '\r', static_cast<std::size_t>(end_ - p_)) != nullptr;
  }

  /// A line ends here: LF, or CR (alone or before LF).
  static bool is_newline(char c) noexcept { return c == '\n' || c == '\r'; }

  /// Throws io_error at the current line; at the end of a file that ends
  /// with a newline, that is the last line, not the empty one after it.
  [[noreturn]] void fail(const std::string& message) const {
    const bool after_last = p_ == end_ && line_ > 1 && end_ != file_->data.data() && is_newline(end_[-1]);
    throw io_error(file_->name, message, after_last ? line_ - 1 : line_);
  }
  std::uint64_t line() const noexcept { return line_; }
  bool at_end() const noexcept { return p_ == end_; }
  const char* position() const noexcept { return p_; }

  /// Backslash-newline counts as a space (OBJ line continuation).
  void set_line_continuation(bool on) noexcept { continuation_ = on; }

  void skip_spaces() noexcept {
    for (;;) {
      while (p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\f' || *p_ == '\v')) ++p_;
      if (continuation_ && p_ != end_ && *p_ == '\\') {
        const char* q = p_ + 1;
        while (q != end_ && (*q == ' ' || *q == '\t')) ++q;
        if (q != end_ && is_newline(*q)) {
          p_ = q;
          pass_newline();
          continue;
        }
      }
      return;
    }
  }
  /// True at the end of the line (after skipping spaces): newline, end of file.
  bool at_eol() noexcept {
    skip_spaces();
    return p_ == end_ || is_newline(*p_);
  }
  /// At end of line or at a '#' comment.
  bool at_eol_or_comment() noexcept { return at_eol() || *p_ == '#'; }

  /// Moves past the next newline (ignoring whatever is left on this line).
  void next_line() noexcept {
    if (has_cr_) {
      while (p_ != end_ && !is_newline(*p_)) ++p_;
      if (p_ != end_) pass_newline();
      return;
    }
    const void* nl = std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_));
    if (!nl) {
      p_ = end_;
      return;
    }
    p_ = static_cast<const char*>(nl) + 1;
    ++line_;
  }

  /// At a newline: moves past it (CRLF as one) and counts the line.
  void pass_newline() noexcept {
    if (*p_ == '\r' && p_ + 1 != end_ && p_[1] == '\n') ++p_;
    ++p_;
    ++line_;
  }

  /// Skips blank lines and lines whose first non-space character is '#'.
  /// Returns false at end of file.
  bool next_content_line() noexcept {
    for (;;) {
      skip_spaces();
      if (p_ == end_) return false;
      if (is_newline(*p_) || *p_ == '#') {
        next_line();
        continue;
      }
      return true;
    }
  }

  /// Skips whitespace including newlines (counting them).
  void skip_whitespace_and_newlines() noexcept {
    for (;;) {
      skip_spaces();
      if (p_ != end_ && is_newline(*p_)) {
        pass_newline();
        continue;
      }
      return;
    }
  }

  /// The next whitespace-delimited token on this line (empty at end of line).
  std::string_view token() noexcept {
    skip_spaces();
    const char* b = p_;
    while (p_ != end_ && !is_space_or_newline(*p_)) ++p_;
    return {b, static_cast<std::size_t>(p_ - b)};
  }

  /// Parses a double; `what` names the value in messages ("x coordinate of vertex 3").
  double read_double(const char* what) {
    skip_spaces();
    if (p_ == end_ || is_newline(*p_)) fail(std::string("line ends before ") + what);
    const char* b = skip_plus_();
    double v = 0;
    auto [ptr, ec] = std::from_chars(b, end_, v);
    // The number must end the token ("1e-400junk" is not a number), also when
    // it is out of range.
    if ((ec != std::errc() && ec != std::errc::result_out_of_range) ||
        (ptr != end_ && !is_space_or_newline(*ptr) && *ptr != '#'))
      bad_token(what, "a number");
    if (ec == std::errc::result_out_of_range) {
      // Overflow or underflow: report overflow as non-finite, accept underflow as 0.
      v = (std::strtod(std::string(b, static_cast<std::size_t>(ptr - b)).c_str(), nullptr));
    }
    p_ = ptr;
    return v;
  }

  /// How many tokens are left on this line before its end or a comment
  /// (the cursor does not move).
  std::size_t tokens_left() const noexcept {
    Text_cursor peek = *this;
    std::size_t n = 0;
    while (!peek.at_eol_or_comment()) {
      (void)peek.token();
      ++n;
    }
    return n;
  }

  /// Parses a signed integer.
  std::int64_t read_int(const char* what) {
    skip_spaces();
    if (p_ == end_ || is_newline(*p_)) fail(std::string("line ends before ") + what);
    std::int64_t v = 0;
    const char* ptr = parse_int_(p_, v);
    if (!ptr || !ends_token_(ptr)) bad_token(what, "an integer");
    p_ = ptr;
    return v;
  }

  /// An OBJ face corner: v, v/vt, v//vn or v/vt/vn (indices as written,
  /// has_vt/has_vn false where absent). "1/", "1//", "1/2/" and "1/x" are
  /// malformed.
  struct Obj_corner {
    std::int64_t v = 0, vt = 0, vn = 0;
    bool has_vt = false, has_vn = false;
  };
  Obj_corner read_obj_corner() {
    skip_spaces();
    if (p_ == end_ || is_newline(*p_)) fail("line ends before vertex index");
    Obj_corner c;
    const char* q = parse_int_(p_, c.v);
    if (q && q != end_ && *q == '/') {
      ++q;
      if (q != end_ && *q != '/') {
        q = parse_int_(q, c.vt);
        c.has_vt = true;
      }
      if (q && q != end_ && *q == '/') {
        q = parse_int_(q + 1, c.vn);
        c.has_vn = true;
      }
    }
    if (!q || !ends_token_(q)) bad_token("vertex index", "an integer");
    p_ = q;
    return c;
  }

  [[noreturn]] void bad_token(const char* what, const char* expected) {
    const char* b = p_;
    const char* e = b;
    while (e != end_ && !is_space_or_newline(*e)) ++e;
    std::string_view tok(b, static_cast<std::size_t>(e - b));
    const bool binary = std::any_of(tok.begin(), tok.end(),
                                    [](char c) { return !is_text_byte(static_cast<unsigned char>(c)); });
    if (binary)
      fail(std::string("binary data where text was expected (reading ") + what + ": " + quote(tok) + ")");
    fail(std::string("malformed ") + what + ": expected " + expected + ", found " + quote(tok));
  }

  static bool is_space_or_newline(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
  }

private:
  // The integer at b (a leading '+' allowed once): the end of its digits,
  // or null when there is none or it is out of range.
  const char* parse_int_(const char* b, std::int64_t& v) const noexcept {
    if (b != end_ && *b == '+') {
      ++b;
      if (b == end_ || *b == '-' || *b == '+') return nullptr;
    }
    const auto [ptr, ec] = std::from_chars(b, end_, v);
    return ec == std::errc() ? ptr : nullptr;
  }
  // A number ends its token: white space, a line end, a comment, or (OBJ)
  // a line continuation.
  bool ends_token_(const char* q) const noexcept {
    return q == end_ || is_space_or_newline(*q) || *q == '#' || (continuation_ && *q == '\\');
  }

  // A leading '+' is allowed once, before a digit or a point ("+-1" and "++1"
  // are not numbers; from_chars alone takes no '+').
  const char* skip_plus_() {
    const char* b = p_;
    if (*b == '+') {
      ++b;
      if (b == end_ || *b == '-' || *b == '+') return p_;   // from_chars fails on '+': reported
    }
    return b;
  }

  // A NUL byte never occurs in a text file: it is the surest sign of binary
  // data, and checking for it once (memchr runs at memory speed) lets the
  // parsers report it precisely rather than as some odd parse error.
  void check_no_nul(std::size_t start) {
    const char* b = file_->data.data() + start;
    const void* z = std::memchr(b, '\0', static_cast<std::size_t>(end_ - b));
    if (!z) return;
    const char* zp = static_cast<const char*>(z);
    std::uint64_t line = line_;
    for (const char* q = b; q != zp; ++q)   // CR, LF and CRLF each end one line
      line += *q == '\n' ? (q == b || q[-1] != '\r') : *q == '\r';
    throw io_error(file_->name,
                   "binary data where text was expected (NUL byte at byte " +
                       std::to_string(zp - file_->data.data()) + ")",
                   line);
  }

  const File_content* file_;
  const char* p_;
  const char* end_;
  std::uint64_t line_;
  bool continuation_ = false;
  bool has_cr_ = false;
};

/// Throws unless all three coordinates are finite.
inline void check_finite(const Eigen::Vector3d& p, std::size_t vertex, const std::string& file,
                         std::optional<std::uint64_t> line, std::optional<std::uint64_t> offset = {}) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
    throw io_error(file,
                   "vertex " + std::to_string(vertex) + " has a non-finite coordinate (NaN or inf)",
                   line, offset);
}

// ---- byte order -------------------------------------------------------------

template <class T>
T byteswap(T v) noexcept {
  static_assert(std::is_trivially_copyable_v<T>);
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  std::reverse(b, b + sizeof(T));
  std::memcpy(&v, b, sizeof(T));
  return v;
}

/// Loads a T stored in `little` or big endian order at p (unaligned).
template <class T>
T load(const char* p, bool little) noexcept {
  T v;
  std::memcpy(&v, p, sizeof(T));
  if (little != (std::endian::native == std::endian::little)) v = byteswap(v);
  return v;
}

/// Appends a T in little-endian order.
template <class T>
void store_le(std::string& out, T v) {
  if constexpr (std::endian::native != std::endian::little) v = byteswap(v);
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

// ---- writing ------------------------------------------------------------------

/// The temporaries of the Atomic_files now open, for
/// remove_pending_temporaries(): fixed slots of fixed-size names whose state
/// (free, being written, ready) is a lock-free atomic, so that a signal
/// handler reads only ready names. Constant-initialized: nothing runs at
/// first use.
struct Pending_temporaries {
  static constexpr int slots = 8;
  static constexpr std::size_t max_path = 4096;
  enum : int { free_slot = 0, writing = 1, ready = 2 };
  std::atomic<int> state[slots] = {};
  char path[slots][max_path] = {};

  /// A slot holding `name`, or -1 if all are taken or the name is too long
  /// (the temporary is then only removed by the destructor).
  int claim(const std::string& name) {
    if (name.size() >= max_path) return -1;
    for (int i = 0; i < slots; ++i) {
      int expected = free_slot;
      if (!state[i].compare_exchange_strong(expected, writing)) continue;
      std::memcpy(path[i], name.c_str(), name.size() + 1);
      state[i].store(ready);
      return i;
    }
    return -1;
  }
  void release(int i) {
    if (i >= 0) state[i].store(free_slot);
  }
};
inline Pending_temporaries pending_temporaries;
static_assert(std::atomic<int>::is_always_lock_free);

/// SIGINT, SIGTERM and SIGHUP held back in this thread for the scope's
/// lifetime (delivered when it ends).
class Terminating_signals_blocked {
public:
  Terminating_signals_blocked() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    ::pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~Terminating_signals_blocked() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  Terminating_signals_blocked(const Terminating_signals_blocked&) = delete;
  Terminating_signals_blocked& operator=(const Terminating_signals_blocked&) = delete;

private:
  sigset_t old_;
};

/// Writes to a temporary file beside the target and renames it over the
/// target on commit(); if commit() is never reached (an exception), the
/// temporary is removed and the target is left as it was. A program that
/// wants the temporary gone on SIGINT/SIGTERM/SIGHUP too calls
/// genmesh::remove_pending_temporaries() from its handler.
///
/// What an in-place overwrite would keep is kept: an existing target's
/// permission bits go to the new file; a symbolic link is written through
/// (its final target is replaced, the link stays); a target the user could
/// not overwrite in place (read-only, or in a directory without write
/// permission) is refused; a target with several hard links is refused
/// (replacing it by rename would silently split the links, and writing into
/// it in place would not be atomic).
class Atomic_file {
public:
  explicit Atomic_file(const std::filesystem::path& target) : target_(target), name_(target.string()) {
    std::error_code ec;
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(target, ec))) {
      // Through the link, however many hops: the link itself stays.
      target_ = std::filesystem::weakly_canonical(target, ec);
      if (ec) throw io_error(name_, "cannot write: cannot resolve the symbolic link: " + ec.message());
    }
    const auto dir = target_.has_parent_path() ? target_.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(dir, ec))
      throw io_error(name_, "cannot write: directory " + dir.string() + " does not exist");
    struct stat st {};
    const bool exists = ::stat(target_.c_str(), &st) == 0;
    if (exists) {
      if (S_ISDIR(st.st_mode)) throw io_error(name_, "cannot write: it is a directory");
      if (!S_ISREG(st.st_mode))
        throw io_error(name_, "cannot write: it exists and is not a regular file (a device, pipe or socket)");
      // Read-only for everyone (0444) is refused even for root, who could
      // write it: the user marked it so.
      if ((st.st_mode & 0222) == 0 || ::access(target_.c_str(), W_OK) != 0)
        throw io_error(name_, "cannot write: the existing file is read-only; genmesh does not replace a file "
                              "that could not be overwritten in place");
      if (st.st_nlink > 1)
        throw io_error(name_, "cannot write: the existing file has " + std::to_string(st.st_nlink) +
                                  " hard links, which replacing it would split; remove it first or write elsewhere");
    }
    // The terminating signals wait while the temporary is created and
    // registered: a signal between the two would leave it behind.
    const Terminating_signals_blocked blocked;
    std::random_device rd;
    for (int attempt = 0; attempt < 16 && !fp_; ++attempt) {
      // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
      std::string temp_name(1, '.');
      temp_name += target_.filename().string();
      temp_name += ".tmp";
      temp_name += std::to_string(rd() % 1000000);
      temp_ = dir / temp_name;
      // "x": fail rather than clobber if the name is taken.
      fp_ = std::fopen(temp_.string().c_str(), "wbx");
      if (!fp_ && errno != EEXIST) break;
    }
    if (!fp_)
      throw io_error(name_, "cannot create a temporary file in " + dir.string() + ": " +
                                std::strerror(errno));
    slot_ = pending_temporaries.claim(temp_.string());
    if (exists) ::fchmod(::fileno(fp_), st.st_mode & 07777);
  }
  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;
  ~Atomic_file() {
    if (fp_) std::fclose(fp_);
    if (!committed_) {
      std::error_code ec;
      std::filesystem::remove(temp_, ec);
    }
    pending_temporaries.release(slot_);
  }

  const std::string& name() const noexcept { return name_; }

  /// Output is collected in `buffer` and flushed in large chunks.
  std::string buffer;

  void flush_if_large() {
    if (buffer.size() >= (1u << 20)) flush();
  }
  void flush() {
    if (!buffer.empty() && std::fwrite(buffer.data(), 1, buffer.size(), fp_) != buffer.size())
      throw io_error(name_, std::string("write failed: ") + std::strerror(errno));
    buffer.clear();
  }

  void commit() {
    flush();
    const int rc = std::fclose(fp_);
    fp_ = nullptr;
    if (rc != 0) throw io_error(name_, std::string("write failed: ") + std::strerror(errno));
    std::error_code ec;
    std::filesystem::rename(temp_, target_, ec);
    if (ec) throw io_error(name_, "cannot rename the temporary file over the target: " + ec.message());
    committed_ = true;
    pending_temporaries.release(slot_);
    slot_ = -1;
  }

private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::string name_;
  std::FILE* fp_ = nullptr;
  bool committed_ = false;
  int slot_ = -1;
};

/// Appends a double: the shortest round-trip form when precision >= 17,
/// else `precision` significant digits.
inline void append_double(std::string& out, double v, int precision) {
  char b[64];
  std::to_chars_result r;
  if (precision >= std::numeric_limits<double>::max_digits10 || precision <= 0)
    r = std::to_chars(b, b + sizeof b, v);
  else
    r = std::to_chars(b, b + sizeof b, v, std::chars_format::general, precision);
  out.append(b, r.ptr);
}

/// Appends "x y z\n" (text formats' vertex lines).
inline void append_point(std::string& out, const Eigen::Vector3d& p, int precision) {
  append_double(out, p.x(), precision);
  out += ' ';
  append_double(out, p.y(), precision);
  out += ' ';
  append_double(out, p.z(), precision);
  out += '\n';
}

template <class I>
void append_int(std::string& out, I v) {
  char b[24];
  auto r = std::to_chars(b, b + sizeof b, v);
  out.append(b, r.ptr);
}

/// Throws io_error for what a writer cannot write: an index out of range,
/// a face with fewer than 3 corners, a non-finite point.
/// A Polygon_soup read the way the writers read a mesh (detail::Soup_view in
/// <genmesh/soup_to_mesh.h>): counts, points in order, faces in order with
/// their corner points on request. The writers take either.
class Soup_source {
 public:
  using Index = Polygon_soup::Index;
  explicit Soup_source(const Polygon_soup& s) noexcept : s_(s) {}
  std::size_t num_points() const noexcept { return s_.num_points(); }
  std::size_t num_faces() const noexcept { return s_.num_faces(); }
  /// The per-point attribute channels (check_attributes_for_write() first).
  std::span<const Soup_attribute> vertex_attributes() const noexcept { return s_.vertex_attributes; }
  template <class F>
  void for_each_point(F&& f) const {
    for (std::size_t v = 0; v < s_.num_points(); ++v) f(v, s_.points[v]);
  }
  /// With points, the corners must be in range (check_face_for_write()
  /// first: a corner out of range gives no point, and an empty span).
  template <bool WithPoints = false, class F>
  void for_each_face(F&& f) const {
    std::vector<Eigen::Vector3d> p;
    for (std::size_t i = 0; i < s_.num_faces(); ++i) {
      const auto c = s_.face(i);
      p.clear();
      if constexpr (WithPoints)
        if (std::all_of(c.begin(), c.end(), [&](Index k) { return k < s_.num_points(); }))
          for (Index k : c) p.push_back(s_.points[k]);
      f(i, c, std::span<const Eigen::Vector3d>(p));
    }
  }

 private:
  const Polygon_soup& s_;
};

inline void check_face_for_write(std::span<const Polygon_soup::Index> c, std::size_t f, std::size_t num_points,
                                 const std::string& file) {
  if (c.size() < 3)
    throw io_error(file, "cannot write: face " + std::to_string(f) + " has " +
                             std::to_string(c.size()) + " corners (at least 3 needed)");
  for (auto i : c)
    if (i >= num_points)
      throw io_error(file, "cannot write: face " + std::to_string(f) + " has index " +
                               std::to_string(i) + " out of range (" +
                               std::to_string(num_points) + " points)");
}
/// Throws io_error unless every channel has width() values per point, all
/// finite, and a component name for each (the PLY writer writes the names).
inline void check_attributes_for_write(std::span<const Soup_attribute> channels, std::size_t num_points,
                                       const std::string& file) {
  for (const Soup_attribute& a : channels) {
    if (a.width() == 0 || a.name.empty())
      throw io_error(file, "cannot write: attribute " + quote(a.name) + " has no name or no components");
    for (const std::string& c : a.components)
      if (c.empty() || std::any_of(c.begin(), c.end(), [](char x) { return Text_cursor::is_space_or_newline(x); }))
        throw io_error(file, "cannot write: attribute " + quote(a.name) + " has a component named " + quote(c) +
                                 " (empty or with white space)");
    if (a.values.size() != num_points * a.width())
      throw io_error(file, "cannot write: attribute " + quote(a.name) + " has " + std::to_string(a.values.size()) +
                               " values for " + std::to_string(num_points) + " points of " +
                               std::to_string(a.width()) + " values each");
    for (std::size_t i = 0; i < a.values.size(); ++i)
      if (!std::isfinite(a.values[i]))
        throw io_error(file, "cannot write: point " + std::to_string(i / a.width()) + " has a non-finite " +
                                 quote(a.components[i % a.width()]) + " value");
  }
}

/// f.template operator()<T>() with T the C++ type of t.
template <class F>
decltype(auto) visit_scalar_type(Scalar_type t, F&& f) {
  switch (t) {
    case Scalar_type::int8: return f.template operator()<std::int8_t>();
    case Scalar_type::uint8: return f.template operator()<std::uint8_t>();
    case Scalar_type::int16: return f.template operator()<std::int16_t>();
    case Scalar_type::uint16: return f.template operator()<std::uint16_t>();
    case Scalar_type::int32: return f.template operator()<std::int32_t>();
    case Scalar_type::uint32: return f.template operator()<std::uint32_t>();
    case Scalar_type::float32: return f.template operator()<float>();
    case Scalar_type::float64: break;
  }
  return f.template operator()<double>();
}

/// Appends an attribute value as text in type t (integers rounded and
/// clamped to the type's range, floats in their shortest round-trip form;
/// doubles as append_double).
inline void append_attribute(std::string& out, double v, Scalar_type t, int precision) {
  visit_scalar_type(t, [&]<class T>() {
    const T x = genmesh::detail::attribute_component<T>(v);
    if constexpr (std::is_same_v<T, double>) {
      append_double(out, x, precision);
    } else {
      char b[32];
      const auto r = std::to_chars(b, b + sizeof b, x);
      out.append(b, r.ptr);
    }
  });
}

/// Appends an attribute value in little-endian binary as type t.
inline void store_attribute_le(std::string& out, double v, Scalar_type t) {
  visit_scalar_type(t, [&]<class T>() { store_le(out, genmesh::detail::attribute_component<T>(v)); });
}

inline void check_point_for_write(const Eigen::Vector3d& p, std::size_t v, const std::string& file) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
    throw io_error(file, "cannot write: point " + std::to_string(v) + " has a non-finite coordinate");
}

} // namespace genmesh::detail::io
