// genmesh/detail/io/ply.h — PLY reader and writer (Stanford polygon format).
//
// Reads ascii, binary_little_endian and binary_big_endian. The `vertex`
// element gives the points from its x, y, z properties (any numeric type, any
// position among other properties); the `face` element gives the faces from
// its `vertex_indices` (or `vertex_index`) list, with any integer count and
// index type. The vertex element's other scalar properties become the soup's
// attribute channels: red green blue [alpha] → "color", nx ny nz → "normal",
// u v (or s t, texture_u texture_v, texture_s texture_t) → "texcoord", any
// other → a channel of its own name; a non-finite value, or an integer
// property whose text is not an integer of its type, is an error naming the
// line (or byte). Other elements and vertex lists are skipped. Writes ascii
// or binary little endian with double coordinates, and each channel's
// components with the type it was read with.
#pragma once

#include <genmesh/detail/io/common.h>

#include <vector>

namespace genmesh::detail::io {

using Ply_type = Scalar_type;

inline std::optional<Ply_type> ply_type_from_name(std::string_view n) {
  if (n == "char" || n == "int8") return Ply_type::int8;
  if (n == "uchar" || n == "uint8") return Ply_type::uint8;
  if (n == "short" || n == "int16") return Ply_type::int16;
  if (n == "ushort" || n == "uint16") return Ply_type::uint16;
  if (n == "int" || n == "int32") return Ply_type::int32;
  if (n == "uint" || n == "uint32") return Ply_type::uint32;
  if (n == "float" || n == "float32") return Ply_type::float32;
  if (n == "double" || n == "float64") return Ply_type::float64;
  return std::nullopt;
}
inline std::size_t ply_size(Ply_type t) {
  switch (t) {
    case Ply_type::int8: case Ply_type::uint8: return 1;
    case Ply_type::int16: case Ply_type::uint16: return 2;
    case Ply_type::int32: case Ply_type::uint32: case Ply_type::float32: return 4;
    case Ply_type::float64: return 8;
  }
  return 0;
}
inline bool ply_is_integer(Ply_type t) { return t != Ply_type::float32 && t != Ply_type::float64; }
inline const char* ply_type_name(Ply_type t) {
  switch (t) {
    case Ply_type::int8: return "char";
    case Ply_type::uint8: return "uchar";
    case Ply_type::int16: return "short";
    case Ply_type::uint16: return "ushort";
    case Ply_type::int32: return "int";
    case Ply_type::uint32: return "uint";
    case Ply_type::float32: return "float";
    case Ply_type::float64: return "double";
  }
  return "double";
}
/// The range of a type's values (as doubles; infinite for floats).
inline std::pair<double, double> ply_integer_range(Ply_type t) {
  return visit_scalar_type(t, []<class T>() {
    if constexpr (std::is_integral_v<T>)
      return std::pair<double, double>(static_cast<double>(std::numeric_limits<T>::lowest()),
                                       static_cast<double>(std::numeric_limits<T>::max()));
    else
      return std::pair<double, double>(-std::numeric_limits<double>::infinity(),
                                       std::numeric_limits<double>::infinity());
  });
}

/// A binary value of type t at p, converted to R: double for coordinates,
/// std::int64_t for counts and indices (only integer types are read so).
template <class R>
R ply_load_as(const char* p, Ply_type t, bool little) {
  switch (t) {
    case Ply_type::int8: return static_cast<R>(static_cast<std::int8_t>(*p));
    case Ply_type::uint8: return static_cast<R>(static_cast<std::uint8_t>(*p));
    case Ply_type::int16: return static_cast<R>(load<std::int16_t>(p, little));
    case Ply_type::uint16: return static_cast<R>(load<std::uint16_t>(p, little));
    case Ply_type::int32: return static_cast<R>(load<std::int32_t>(p, little));
    case Ply_type::uint32: return static_cast<R>(load<std::uint32_t>(p, little));
    case Ply_type::float32: return static_cast<R>(load<float>(p, little));
    case Ply_type::float64: return static_cast<R>(load<double>(p, little));
  }
  return R{};
}
inline double ply_load_double(const char* p, Ply_type t, bool little) { return ply_load_as<double>(p, t, little); }
inline std::int64_t ply_load_int(const char* p, Ply_type t, bool little) {
  return ply_load_as<std::int64_t>(p, t, little);
}

struct Ply_property {
  std::string name;
  std::uint64_t line = 0;   ///< of its header line, for messages
  bool is_list = false;
  Ply_type count_type = Ply_type::uint8;
  Ply_type type = Ply_type::float32;
};
struct Ply_element {
  std::string name;
  std::uint64_t line = 0;   ///< of its header line, for messages
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
};

/// Where a vertex property's value goes: channel and component (channel -1:
/// not an attribute — a coordinate or a list).
struct Ply_attribute_slot {
  int channel = -1;
  std::size_t component = 0;
};

/// The attribute channels of a vertex element (names, components, types;
/// no values yet) and each property's slot. xyz: the coordinates' properties.
inline std::vector<Ply_attribute_slot> ply_vertex_channels(const Ply_element& vertex, const int xyz[3],
                                                           std::vector<Soup_attribute>& channels) {
  const auto& props = vertex.properties;
  std::vector<Ply_attribute_slot> slot(props.size());
  const auto find = [&](std::string_view name) -> int {
    for (std::size_t i = 0; i < props.size(); ++i)
      if (props[i].name == name && !props[i].is_list && static_cast<int>(i) != xyz[0] &&
          static_cast<int>(i) != xyz[1] && static_cast<int>(i) != xyz[2] && slot[i].channel < 0)
        return static_cast<int>(i);
    return -1;
  };
  // Named groups first (a group needs all its members; alpha is optional),
  // then every other scalar property alone; channels in the order of their
  // first property.
  struct Group {
    const char* name;
    std::vector<std::vector<const char*>> spellings;
    bool optional_last;
  };
  const Group groups[] = {{"color", {{"red", "green", "blue", "alpha"}}, true},
                          {"normal", {{"nx", "ny", "nz"}}, false},
                          {"texcoord", {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}, false}};
  std::vector<std::pair<int, Soup_attribute>> found; // (first property, channel)
  std::vector<std::vector<int>> members;
  for (const Group& g : groups) {
    for (const auto& names : g.spellings) {
      std::vector<int> at;
      for (const char* n : names) at.push_back(find(n));
      if (g.optional_last && at.back() < 0) at.pop_back();
      if (std::find(at.begin(), at.end(), -1) != at.end()) continue;
      Soup_attribute a;
      a.name = g.name;
      for (int i : at) {
        a.components.push_back(props[static_cast<std::size_t>(i)].name);
        slot[static_cast<std::size_t>(i)].channel = 0; // taken; numbered below
      }
      found.emplace_back(*std::min_element(at.begin(), at.end()), std::move(a));
      members.push_back(std::move(at));
      break;
    }
  }
  for (std::size_t i = 0; i < props.size(); ++i) {
    if (props[i].is_list || slot[i].channel >= 0 || static_cast<int>(i) == xyz[0] || static_cast<int>(i) == xyz[1] ||
        static_cast<int>(i) == xyz[2])
      continue;
    Soup_attribute a;
    a.name = props[i].name;
    a.components = {props[i].name};
    slot[i].channel = 0;
    found.emplace_back(static_cast<int>(i), std::move(a));
    members.push_back({static_cast<int>(i)});
  }
  std::vector<std::size_t> order(found.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return found[a].first < found[b].first; });
  for (const std::size_t k : order) {
    Soup_attribute& a = found[k].second;
    const auto& m = members[k];
    // One type for the channel: the members' common type, else double.
    a.type = props[static_cast<std::size_t>(m.front())].type;
    for (int i : m)
      if (props[static_cast<std::size_t>(i)].type != a.type) a.type = Ply_type::float64;
    for (std::size_t c = 0; c < m.size(); ++c)
      slot[static_cast<std::size_t>(m[c])] = {static_cast<int>(channels.size()), c};
    channels.push_back(std::move(a));
  }
  return slot;
}

struct Ply_header {
  enum class Format { ascii, binary_little_endian, binary_big_endian } format = Format::ascii;
  std::vector<Ply_element> elements;
  std::size_t body_offset = 0;   ///< first byte after end_header's newline
  std::uint64_t body_line = 0;   ///< line number of the body's first line
  std::uint64_t end_line = 0;    ///< line number of end_header
};

inline Ply_header read_ply_header(const File_content& file) {
  Ply_header h;
  Text_cursor in(file, 0, 1, /*text_only=*/false);
  if (in.token() != "ply" || !in.at_eol()) in.fail("not a PLY file: the first line must be 'ply'");
  in.next_line();
  bool have_format = false;
  for (;;) {
    if (in.at_end()) in.fail("missing end_header: the file ends inside the PLY header");
    const std::string_view kw = in.token();
    if (kw == "end_header") {
      h.end_line = in.line();
      in.next_line();
      break;
    }
    if (kw.empty() || kw == "comment" || kw == "obj_info") {
      in.next_line();
      continue;
    }
    if (kw == "format") {
      const auto f = in.token();
      if (f == "ascii") h.format = Ply_header::Format::ascii;
      else if (f == "binary_little_endian") h.format = Ply_header::Format::binary_little_endian;
      else if (f == "binary_big_endian") h.format = Ply_header::Format::binary_big_endian;
      else in.fail("unknown PLY format " + quote(f));
      if (in.token() != "1.0") in.fail("unsupported PLY version (1.0 expected)");
      have_format = true;
    } else if (kw == "element") {
      Ply_element e;
      e.line = in.line();
      e.name = std::string(in.token());
      if (e.name.empty()) in.fail("element without a name");
      const std::int64_t n = in.read_int("element count");
      if (n < 0) in.fail("negative count for element '" + e.name + "'");
      e.count = static_cast<std::uint64_t>(n);
      h.elements.push_back(std::move(e));
    } else if (kw == "property") {
      if (h.elements.empty()) in.fail("property before any element");
      Ply_property p;
      p.line = in.line();
      auto t = in.token();
      if (t == "list") {
        p.is_list = true;
        const auto ct = in.token();
        const auto c = ply_type_from_name(ct);
        if (!c) in.fail("unknown PLY type " + quote(ct));
        if (!ply_is_integer(*c)) in.fail("list count type " + quote(ct) + " is not an integer type");
        p.count_type = *c;
        t = in.token();
      }
      const auto ty = ply_type_from_name(t);
      if (!ty) in.fail("unknown PLY type " + quote(t));
      p.type = *ty;
      p.name = std::string(in.token());
      if (p.name.empty()) in.fail("property without a name");
      h.elements.back().properties.push_back(std::move(p));
    } else {
      in.fail("unknown PLY header keyword " + quote(kw));
    }
    if (!in.at_eol()) in.fail("unexpected " + quote(in.token()) + " at the end of a header line");
    in.next_line();
  }
  if (!have_format) in.fail("the PLY header has no format line");
  h.body_offset = static_cast<std::size_t>(in.position() - file.data.data());
  h.body_line = in.line();
  return h;
}

inline Polygon_soup read_ply(const File_content& file) {
  const Ply_header h = read_ply_header(file);
  const Ply_element* vertex = nullptr;
  const Ply_element* face = nullptr;
  for (const auto& e : h.elements) {
    if (e.name == "vertex" && !vertex) vertex = &e;
    if (e.name == "face" && !face) face = &e;
  }
  if (!vertex) throw io_error(file.name, "the PLY header has no vertex element", h.end_line);
  int xyz[3] = {-1, -1, -1};
  for (std::size_t i = 0; i < vertex->properties.size(); ++i) {
    const auto& p = vertex->properties[i];
    for (int k = 0; k < 3; ++k)
      if (p.name == std::string_view("xyz").substr(static_cast<std::size_t>(k), 1) && !p.is_list && xyz[k] < 0) xyz[k] = static_cast<int>(i);
  }
  for (int k = 0; k < 3; ++k)
    if (xyz[k] < 0)
      throw io_error(file.name, std::string("the PLY vertex element has no scalar '") + "xyz"[k] +
                                    "' property", vertex->line);
  int corners = -1;
  if (face) {
    for (std::size_t i = 0; i < face->properties.size(); ++i) {
      const auto& p = face->properties[i];
      if ((p.name == "vertex_indices" || p.name == "vertex_index") && corners < 0) {
        if (!p.is_list) throw io_error(file.name, "the PLY face property '" + p.name + "' is not a list", p.line);
        if (!ply_is_integer(p.type))
          throw io_error(file.name, "the PLY face property '" + p.name + "' has a non-integer index type", p.line);
        corners = static_cast<int>(i);
      }
    }
    if (corners < 0) throw io_error(file.name, "the PLY face element has no vertex_indices list", face->line);
  }
  if (vertex->count > std::numeric_limits<Polygon_soup::Index>::max())
    throw io_error(file.name, "too many vertices: " + std::to_string(vertex->count), vertex->line);

  Polygon_soup soup;
  const auto cap = file.data.size() / 2 + 1;
  soup.points.reserve(std::min<std::size_t>(vertex->count, cap));
  if (face) {
    soup.offsets.reserve(std::min<std::size_t>(face->count, cap) + 1);
    soup.indices.reserve(std::min<std::size_t>(face->count, cap / 3) * 3);
  }
  const std::vector<Ply_attribute_slot> slot = ply_vertex_channels(*vertex, xyz, soup.vertex_attributes);
  for (auto& a : soup.vertex_attributes)
    a.values.reserve(std::min<std::size_t>(vertex->count * a.width(), file.data.size()));
  // Room for vertex i's attribute values (0 until read).
  const auto open_vertex = [&] {
    for (auto& a : soup.vertex_attributes) a.values.resize(a.values.size() + a.width(), 0.0);
  };
  // Why value v of vertex property k cannot be an attribute value, or empty.
  const auto bad_value = [&](std::size_t k, double v, bool text) -> std::string {
    const auto& prop = vertex->properties[k];
    if (!std::isfinite(v)) return "non-finite value of vertex property '" + prop.name + "'";
    if (text && ply_is_integer(prop.type)) {
      const auto [lo, hi] = ply_integer_range(prop.type);
      if (v != std::trunc(v) || v < lo || v > hi) {
        char b[32];
        std::snprintf(b, sizeof b, "%.17g", v);
        return std::string("malformed value of vertex property '") + prop.name + "': " + b + " is not a " +
               ply_type_name(prop.type);
      }
    }
    return {};
  };
  // Stores vertex i's value of property k (an attribute: slot[k].channel >= 0).
  const auto store = [&](std::uint64_t i, std::size_t k, double v) {
    auto& a = soup.vertex_attributes[static_cast<std::size_t>(slot[k].channel)];
    a.values[static_cast<std::size_t>(i) * a.width() + slot[k].component] = v;
  };
  const std::int64_t nv = static_cast<std::int64_t>(vertex->count);
  const auto index_error = [&](std::uint64_t f, std::int64_t idx) {
    return "face " + std::to_string(f) + " has index " + std::to_string(idx) + " out of range (" +
           std::to_string(nv) + " vertices)";
  };

  if (h.format == Ply_header::Format::ascii) {
    Text_cursor in(file, h.body_offset, h.body_line);
    for (const auto& e : h.elements) {
      // An element without properties has no data, whatever its count:
      // looping over the count would do nothing for up to 2^63 rounds.
      if (e.properties.empty()) continue;
      const bool is_vertex = &e == vertex, is_face = &e == face;
      for (std::uint64_t i = 0; i < e.count; ++i) {
        Eigen::Vector3d p(0, 0, 0);
        if (is_vertex) open_vertex();
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
          const auto& prop = e.properties[k];
          in.skip_whitespace_and_newlines();
          if (in.at_end())
            in.fail("truncated: the header says " + std::to_string(e.count) + " '" + e.name +
                    "' elements, the data ends in number " + std::to_string(i));
          if (prop.is_list) {
            const std::int64_t n = in.read_int("list count");
            if (n < 0) in.fail("negative list count in element '" + e.name + "' number " + std::to_string(i));
            const bool take = is_face && static_cast<int>(k) == corners;
            if (take && n < 3)
              in.fail("face " + std::to_string(i) + " has " + std::to_string(n) +
                      " corners (at least 3 needed)");
            for (std::int64_t j = 0; j < n; ++j) {
              in.skip_whitespace_and_newlines();
              if (in.at_end()) in.fail("truncated: the data ends inside a list of element '" + e.name + "'");
              if (take) {
                const std::int64_t idx = in.read_int("vertex index");
                if (idx < 0 || idx >= nv) in.fail(index_error(i, idx));
                soup.indices.push_back(static_cast<Polygon_soup::Index>(idx));
              } else {
                (void)in.read_double("list value");
              }
            }
          } else if (is_vertex && (static_cast<int>(k) == xyz[0] || static_cast<int>(k) == xyz[1] ||
                                   static_cast<int>(k) == xyz[2])) {
            double v = in.read_double("coordinate");
            // A float property holds a float, whatever digits the text has.
            if (prop.type == Ply_type::float32)
              v = std::abs(v) <= std::numeric_limits<float>::max()
                      ? static_cast<double>(static_cast<float>(v))
                      : std::copysign(std::numeric_limits<double>::infinity(), v);   // then refused
            else if (ply_is_integer(prop.type)) v = std::trunc(v);
            for (int c = 0; c < 3; ++c)
              if (static_cast<int>(k) == xyz[c]) p[c] = v;
          } else if (is_vertex && slot[k].channel >= 0) {
            const double v = in.read_double("vertex property value");
            if (const std::string why = bad_value(k, v, true); !why.empty())
              in.fail(why + " (vertex " + std::to_string(i) + ")");
            store(i, k, v);
          } else {
            // Skipped values are only checked to be numbers ("255" or "1.0"
            // alike, whatever the declared type).
            (void)in.read_double("property value");
          }
        }
        if (is_vertex) {
          check_finite(p, i, file.name, in.line());
          soup.points.push_back(p);
        }
        if (is_face) soup.offsets.push_back(static_cast<Polygon_soup::Index>(soup.indices.size()));
      }
    }
    return soup;
  }

  const bool little = h.format == Ply_header::Format::binary_little_endian;
  const char* const base = file.data.data();
  const char* p = base + h.body_offset;
  const char* const end = base + file.data.size();
  const auto offset = [&](const char* q) { return static_cast<std::uint64_t>(q - base); };
  // Vertex i's binary value of attribute property k, at q.
  const auto load_attribute = [&](std::uint64_t i, std::size_t k, const char* q) {
    const double v = ply_load_double(q, vertex->properties[k].type, little);
    if (const std::string why = bad_value(k, v, false); !why.empty())
      throw io_error(file.name, why + " (vertex " + std::to_string(i) + ")", std::nullopt, offset(q));
    store(i, k, v);
  };
  const auto truncated = [&](const Ply_element& e, std::uint64_t i) {
    return io_error(file.name,
                    "truncated: the header says " + std::to_string(e.count) + " '" + e.name +
                        "' elements, the data ends in number " + std::to_string(i),
                    std::nullopt, offset(p));
  };
  for (const auto& e : h.elements) {
    const bool is_vertex = &e == vertex, is_face = &e == face;
    const bool fixed = std::none_of(e.properties.begin(), e.properties.end(),
                                    [](const Ply_property& q) { return q.is_list; });
    if (fixed) {
      std::size_t stride = 0;
      std::size_t at[3] = {0, 0, 0};
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        for (int c = 0; c < 3; ++c)
          if (is_vertex && static_cast<int>(k) == xyz[c]) at[c] = stride;
        stride += ply_size(e.properties[k].type);
      }
      const auto avail = static_cast<std::uint64_t>(end - p);
      if (stride != 0 && avail / stride < e.count) {
        p += (avail / stride) * stride;
        throw truncated(e, avail / stride);
      }
      if (is_vertex) {
        const Ply_type tx = e.properties[xyz[0]].type, ty = e.properties[xyz[1]].type,
                       tz = e.properties[xyz[2]].type;
        // The attribute properties and where each lies in a vertex's record.
        std::vector<std::pair<std::size_t, std::size_t>> attribute_at; // (property, byte offset)
        for (std::size_t k = 0, o = 0; k < e.properties.size(); o += ply_size(e.properties[k].type), ++k)
          if (slot[k].channel >= 0) attribute_at.emplace_back(k, o);
        for (std::uint64_t i = 0; i < e.count; ++i, p += stride) {
          const Eigen::Vector3d q(ply_load_double(p + at[0], tx, little),
                                  ply_load_double(p + at[1], ty, little),
                                  ply_load_double(p + at[2], tz, little));
          check_finite(q, i, file.name, std::nullopt, offset(p));
          soup.points.push_back(q);
          open_vertex();
          for (const auto& [k, o] : attribute_at) load_attribute(i, k, p + o);
        }
      } else {
        p += stride * e.count;
      }
      continue;
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const char* const start = p;
      Eigen::Vector3d point(0, 0, 0);
      if (is_vertex) open_vertex();
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const auto& prop = e.properties[k];
        if (!prop.is_list) {
          const std::size_t s = ply_size(prop.type);
          if (static_cast<std::size_t>(end - p) < s) {
            p = start;
            throw truncated(e, i);
          }
          if (is_vertex) {
            for (int c = 0; c < 3; ++c)
              if (static_cast<int>(k) == xyz[c]) point[c] = ply_load_double(p, prop.type, little);
            if (slot[k].channel >= 0) load_attribute(i, k, p);
          }
          p += s;
          continue;
        }
        const std::size_t cs = ply_size(prop.count_type);
        if (static_cast<std::size_t>(end - p) < cs) {
          p = start;
          throw truncated(e, i);
        }
        const std::int64_t n = ply_load_int(p, prop.count_type, little);
        if (n < 0)
          throw io_error(file.name, "negative list count in element '" + e.name + "' number " + std::to_string(i),
                         std::nullopt, offset(p));
        const bool take = is_face && static_cast<int>(k) == corners;
        if (take && n < 3)
          throw io_error(file.name, "face " + std::to_string(i) + " has " + std::to_string(n) +
                                        " corners (at least 3 needed)",
                         std::nullopt, offset(p));
        p += cs;
        const std::size_t is = ply_size(prop.type);
        if (static_cast<std::uint64_t>(end - p) / is < static_cast<std::uint64_t>(n)) {
          p = start;
          throw truncated(e, i);
        }
        if (take) {
          for (std::int64_t j = 0; j < n; ++j, p += is) {
            const std::int64_t idx = ply_load_int(p, prop.type, little);
            if (idx < 0 || idx >= nv) throw io_error(file.name, index_error(i, idx), std::nullopt, offset(p));
            soup.indices.push_back(static_cast<Polygon_soup::Index>(idx));
          }
        } else {
          p += is * static_cast<std::size_t>(n);
        }
      }
      if (is_vertex) {
        check_finite(point, i, file.name, std::nullopt, offset(start));
        soup.points.push_back(point);
      }
      if (is_face) soup.offsets.push_back(static_cast<Polygon_soup::Index>(soup.indices.size()));
    }
  }
  return soup;
}

/// Writes `soup` (Soup_source or detail::Soup_view) as PLY.
template <class Source>
void write_ply(Atomic_file& out, const Source& soup, bool binary, int precision) {
  std::size_t max_corners = 0;
  soup.for_each_face([&](std::size_t, std::span<const Polygon_soup::Index> c, auto) {
    max_corners = std::max(max_corners, c.size());
  });
  // uchar counts and int indices are what every PLY reader accepts; wider
  // types only when the soup needs them.
  const bool wide_count = max_corners > 255;
  const bool wide_index = soup.num_points() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  const auto channels = soup.vertex_attributes();
  check_attributes_for_write(channels, soup.num_points(), out.name());
  std::string& b = out.buffer;
  b += "ply\nformat ";
  b += binary ? "binary_little_endian" : "ascii";
  b += " 1.0\ncomment written by genmesh\nelement vertex ";
  append_int(b, soup.num_points());
  b += "\nproperty double x\nproperty double y\nproperty double z";
  for (const Soup_attribute& a : channels)
    for (const std::string& c : a.components) {
      b += "\nproperty ";
      b += ply_type_name(a.type);
      b += ' ';
      b += c;
    }
  b += "\nelement face ";
  append_int(b, soup.num_faces());
  b += "\nproperty list ";
  b += wide_count ? "uint " : "uchar ";
  b += wide_index ? "uint" : "int";
  b += " vertex_indices\nend_header\n";
  soup.for_each_point([&](std::size_t v, const Eigen::Vector3d& p) {
    check_point_for_write(p, v, out.name());
    if (binary) {
      store_le(b, p.x());
      store_le(b, p.y());
      store_le(b, p.z());
      for (const Soup_attribute& a : channels)
        for (const double x : a.of(v)) store_attribute_le(b, x, a.type);
    } else {
      append_point(b, p, precision);
      if (!channels.empty()) {
        b.pop_back(); // the point's newline: its attributes follow on its line
        for (const Soup_attribute& a : channels)
          for (const double x : a.of(v)) {
            b += ' ';
            append_attribute(b, x, a.type, precision);
          }
        b += '\n';
      }
    }
    out.flush_if_large();
  });
  soup.for_each_face([&](std::size_t f, std::span<const Polygon_soup::Index> c, auto) {
    check_face_for_write(c, f, soup.num_points(), out.name());
    if (binary) {
      if (wide_count) store_le(b, static_cast<std::uint32_t>(c.size()));
      else b += static_cast<char>(static_cast<std::uint8_t>(c.size()));
      for (auto i : c) {
        if (wide_index) store_le(b, static_cast<std::uint32_t>(i));
        else store_le(b, static_cast<std::int32_t>(i));
      }
    } else {
      append_int(b, c.size());
      for (auto i : c) {
        b += ' ';
        append_int(b, i);
      }
      b += '\n';
    }
    out.flush_if_large();
  });
}

} // namespace genmesh::detail::io
