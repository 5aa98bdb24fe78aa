// genmesh/exceptions.h — the typed errors genmesh throws.
//
// Every error names what it is about: the element for invalid_input, the file
// and the line or byte offset for io_error.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace genmesh {

/// Thrown when a precondition on the input fails (a non-triangle face given to
/// a triangle algorithm, a non-manifold soup given to a halfedge builder, …).
/// what() names the offending element.
class invalid_input : public std::runtime_error {
public:
  explicit invalid_input(const std::string& message) : std::runtime_error(message) {}
};

/// Thrown by reading and writing meshes. what() reads
/// "<file>:<line>: <message>" for text formats, "<file>: byte <offset>: <message>"
/// for binary ones, or "<file>: <message>" when no position applies.
class io_error : public std::runtime_error {
public:
  io_error(std::string file, std::string message,
           std::optional<std::uint64_t> line = std::nullopt,
           std::optional<std::uint64_t> byte_offset = std::nullopt)
      : std::runtime_error(format(file, message, line, byte_offset)),
        file_(std::move(file)), message_(std::move(message)), line_(line),
        byte_offset_(byte_offset) {}

  const std::string& file() const noexcept { return file_; }
  /// The message without the position prefix.
  const std::string& message() const noexcept { return message_; }
  /// 1-based line number, for text formats.
  std::optional<std::uint64_t> line() const noexcept { return line_; }
  /// 0-based byte offset, for binary formats.
  std::optional<std::uint64_t> byte_offset() const noexcept { return byte_offset_; }

private:
  static std::string format(const std::string& file, const std::string& message,
                            std::optional<std::uint64_t> line,
                            std::optional<std::uint64_t> byte_offset) {
    std::string s = file;
    if (line) s += ":" + std::to_string(*line);
    if (byte_offset) s += ": byte " + std::to_string(*byte_offset);
    return s + ": " + message;
  }

  std::string file_;
  std::string message_;
  std::optional<std::uint64_t> line_;
  std::optional<std::uint64_t> byte_offset_;
};

} // namespace genmesh
