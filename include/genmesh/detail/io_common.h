// genmesh/detail/io_common.h — machinery shared by the readers and writers:
// whole-file reading, a text cursor that counts lines, number parsing with
// std::from_chars, byte-order helpers, and the atomic file writer.
//
// Private to <genmesh/io.h>; nothing here is API.
#pragma once

#include <genmesh/exceptions.h>
#include <genmesh/polygon_soup.h>

#include <algorithm>
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
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace genmesh::detail::io {

/// A file's whole content and its name, as the errors print it.
struct File_content {
  std::string name;
  std::string data;
};

/// Reads the whole file; throws io_error if it is missing, unreadable or empty.
inline File_content read_whole_file(const std::filesystem::path& path) {
  File_content f{path.string(), {}};
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw io_error(f.name, "file does not exist");
  if (std::filesystem::is_directory(status)) throw io_error(f.name, "is a directory, not a file");
  std::FILE* fp = std::fopen(f.name.c_str(), "rb");
  if (!fp) throw io_error(f.name, std::string("cannot open file: ") + std::strerror(errno));
  // One fread of the whole file when its size is known; chunks otherwise
  // (pipes and other special files).
  std::string data;
  if (std::fseek(fp, 0, SEEK_END) == 0) {
    const long size = std::ftell(fp);
    std::fseek(fp, 0, SEEK_SET);
    if (size > 0) {
      data.resize(static_cast<std::size_t>(size));
      data.resize(std::fread(data.data(), 1, data.size(), fp));
    }
  }
  char chunk[1 << 14];
  std::size_t n;
  while ((n = std::fread(chunk, 1, sizeof chunk, fp)) > 0) data.append(chunk, n);
  const bool failed = std::ferror(fp) != 0;
  std::fclose(fp);
  if (failed) throw io_error(f.name, "read error");
  if (data.empty()) throw io_error(f.name, "file is empty");
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

/// Cursor over a text buffer. Lines are 1-based; whitespace within a line is
/// space, tab, \r, \f, \v. Every error it throws names the file and the line.
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
  }

  /// Throws io_error at the current line; at the end of a file that ends
  /// with a newline, that is the last line, not the empty one after it.
  [[noreturn]] void fail(const std::string& message) const {
    const bool after_last = p_ == end_ && line_ > 1 && end_ != file_->data.data() && end_[-1] == '\n';
    throw io_error(file_->name, message, after_last ? line_ - 1 : line_);
  }
  std::uint64_t line() const noexcept { return line_; }
  bool at_end() const noexcept { return p_ == end_; }
  const char* position() const noexcept { return p_; }

  /// Backslash-newline counts as a space (OBJ line continuation).
  void set_line_continuation(bool on) noexcept { continuation_ = on; }

  void skip_spaces() noexcept {
    for (;;) {
      while (p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\f' || *p_ == '\v'))
        ++p_;
      if (continuation_ && p_ != end_ && *p_ == '\\') {
        const char* q = p_ + 1;
        while (q != end_ && (*q == ' ' || *q == '\t' || *q == '\r')) ++q;
        if (q != end_ && *q == '\n') {
          p_ = q + 1;
          ++line_;
          continue;
        }
      }
      return;
    }
  }
  /// True at the end of the line (after skipping spaces): newline, end of file.
  bool at_eol() noexcept {
    skip_spaces();
    return p_ == end_ || *p_ == '\n';
  }
  /// At end of line or at a '#' comment.
  bool at_eol_or_comment() noexcept { return at_eol() || *p_ == '#'; }

  /// Moves past the next newline (ignoring whatever is left on this line).
  void next_line() noexcept {
    const void* nl = std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_));
    if (!nl) {
      p_ = end_;
      return;
    }
    p_ = static_cast<const char*>(nl) + 1;
    ++line_;
  }

  /// Skips blank lines and lines whose first non-space character is '#'.
  /// Returns false at end of file.
  bool next_content_line() noexcept {
    for (;;) {
      skip_spaces();
      if (p_ == end_) return false;
      if (*p_ == '\n' || *p_ == '#') {
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
      if (p_ != end_ && *p_ == '\n') {
        ++p_;
        ++line_;
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
    if (p_ == end_ || *p_ == '\n') fail(std::string("line ends before ") + what);
    const char* b = p_;
    if (*b == '+') ++b;
    double v = 0;
    auto [ptr, ec] = std::from_chars(b, end_, v);
    if (ec == std::errc::result_out_of_range) {
      // Overflow or underflow: report overflow as non-finite, accept underflow as 0.
      v = (std::strtod(std::string(b, static_cast<std::size_t>(ptr - b)).c_str(), nullptr));
    } else if (ec != std::errc() || (ptr != end_ && !is_space_or_newline(*ptr) && *ptr != '#')) {
      bad_token(what, "a number");
    }
    p_ = ptr;
    return v;
  }

  /// Parses a signed integer. With `slash_suffix`, a suffix like "/2/3" or
  /// "//3" after the number is skipped (OBJ's v/vt/vn corners).
  std::int64_t read_int(const char* what, bool slash_suffix = false) {
    skip_spaces();
    if (p_ == end_ || *p_ == '\n') fail(std::string("line ends before ") + what);
    const char* b = p_;
    if (*b == '+') ++b;
    std::int64_t v = 0;
    auto [ptr, ec] = std::from_chars(b, end_, v);
    if (ec == std::errc() && slash_suffix && ptr != end_ && *ptr == '/') {
      while (ptr != end_ && (*ptr == '/' || *ptr == '-' || *ptr == '+' || (*ptr >= '0' && *ptr <= '9')))
        ++ptr;
    }
    if (ec != std::errc() || (ptr != end_ && !is_space_or_newline(*ptr) && *ptr != '#' &&
                              !(continuation_ && *ptr == '\\')))
      bad_token(what, "an integer");
    p_ = ptr;
    return v;
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
  // A NUL byte never occurs in a text file: it is the surest sign of binary
  // data, and checking for it once (memchr runs at memory speed) lets the
  // parsers report it precisely rather than as some odd parse error.
  void check_no_nul(std::size_t start) {
    const char* b = file_->data.data() + start;
    const void* z = std::memchr(b, '\0', static_cast<std::size_t>(end_ - b));
    if (!z) return;
    const char* zp = static_cast<const char*>(z);
    const auto line = line_ + static_cast<std::uint64_t>(std::count(b, zp, '\n'));
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

/// Writes to a temporary file beside the target and renames it over the
/// target on commit(); if commit() is never reached (an exception), the
/// temporary is removed and the target is left as it was.
class Atomic_file {
public:
  explicit Atomic_file(const std::filesystem::path& target) : target_(target), name_(target.string()) {
    const auto dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
      throw io_error(name_, "cannot write: directory " + dir.string() + " does not exist");
    if (std::filesystem::is_directory(target, ec))
      throw io_error(name_, "cannot write: it is a directory");
    std::random_device rd;
    for (int attempt = 0; attempt < 16 && !fp_; ++attempt) {
      // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
      std::string temp_name(1, '.');
      temp_name += target.filename().string();
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
  }
  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;
  ~Atomic_file() {
    if (fp_) std::fclose(fp_);
    if (!committed_) {
      std::error_code ec;
      std::filesystem::remove(temp_, ec);
    }
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
  }

private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::string name_;
  std::FILE* fp_ = nullptr;
  bool committed_ = false;
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
inline void check_face_for_write(const Polygon_soup& soup, std::size_t f, const std::string& file) {
  const auto c = soup.face(f);
  if (c.size() < 3)
    throw io_error(file, "cannot write: face " + std::to_string(f) + " has " +
                             std::to_string(c.size()) + " corners (at least 3 needed)");
  for (auto i : c)
    if (i >= soup.num_points())
      throw io_error(file, "cannot write: face " + std::to_string(f) + " has index " +
                               std::to_string(i) + " out of range (" +
                               std::to_string(soup.num_points()) + " points)");
}
inline void check_point_for_write(const Polygon_soup& soup, std::size_t v, const std::string& file) {
  const auto& p = soup.points[v];
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
    throw io_error(file, "cannot write: point " + std::to_string(v) + " has a non-finite coordinate");
}

} // namespace genmesh::detail::io
