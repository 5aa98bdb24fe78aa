// genmesh/detail/properties/property_array.h — typed, dynamically added per-element arrays.
//
// The storage behind Halfedge_mesh's properties: one Property_container per
// element kind (vertex, halfedge, edge, face) owns any number of named or
// anonymous Property_array<T>, all of the container's size. Elements are
// added, reset, and compacted for every array at once; those whole-array
// operations go through a virtual interface (rare, bulk), element access does
// not (a handle holds the typed array and indexes its std::vector directly).
//
// bool is stored as one byte per element (Bool_box), not std::vector<bool>,
// so that operator[] returns a real bool& and the handle is a boost lvalue
// property map like every other type.
#pragma once

#include <genmesh/detail/elements/compaction.h>
#include <genmesh/detail/memory/huge_pages.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <vector>

namespace genmesh::detail {

/// One bool in its own byte, so a reference to it is a plain bool&.
struct Bool_box {
  bool value = false;
  Bool_box() = default;
  Bool_box(bool b) : value(b) {} // NOLINT: implicit on purpose (vector construction)
};

template <class T>
struct Property_storage {
  using type = T;
  static T& ref(T& x) { return x; }
  static const T& ref(const T& x) { return x; }
};
template <>
struct Property_storage<bool> {
  using type = Bool_box;
  static bool& ref(Bool_box& x) { return x.value; }
  static const bool& ref(const Bool_box& x) { return x.value; }
};

/// The untyped face of a property array: what the container does to all arrays.
class Base_property_array {
public:
  explicit Base_property_array(std::string name) : name_(std::move(name)) {}
  virtual ~Base_property_array() = default;
  Base_property_array(const Base_property_array&) = default;
  Base_property_array& operator=(const Base_property_array&) = default;

  virtual void reserve(std::size_t n) = 0;
  virtual void resize(std::size_t n) = 0;
  virtual void push_back() = 0;
  /// Element i gets the default value again (a recycled element).
  virtual void reset(std::size_t i) = 0;
  /// Element i moves to old_to_new[i] if that is not `dropped`; then the array
  /// shrinks to new_size. Each destination must be i itself or a dropped slot.
  virtual void compact(std::span<const std::uint32_t> old_to_new, std::size_t new_size) = 0;
  /// Element i moves to perm[i], perm a permutation of [0, size()) (see
  /// detail::full_permutation); then the array shrinks to new_size. In place.
  virtual void permute(std::span<const std::uint32_t> perm, std::size_t new_size) = 0;
  virtual void shrink_to_fit() = 0;
  [[nodiscard]] virtual std::unique_ptr<Base_property_array> clone() const = 0;
  [[nodiscard]] virtual std::size_t memory_bytes() const = 0;
  [[nodiscard]] virtual const std::type_info& value_type() const = 0;

  [[nodiscard]] const std::string& name() const { return name_; }

  static constexpr std::uint32_t dropped = static_cast<std::uint32_t>(-1);

private:
  std::string name_;
};

template <class T>
class Property_array final : public Base_property_array {
public:
  using Storage = typename Property_storage<T>::type;

  Property_array(std::string name, T default_value, std::size_t size)
      : Base_property_array(std::move(name)), default_(std::move(default_value)),
        data_(size, Storage(default_)) {}

  void reserve(std::size_t n) override { data_.reserve(n); }
  void resize(std::size_t n) override { data_.resize(n, Storage(default_)); }
  void push_back() override { data_.push_back(Storage(default_)); }
  void reset(std::size_t i) override { data_[i] = Storage(default_); }
  void compact(std::span<const std::uint32_t> old_to_new, std::size_t new_size) override {
    for (std::size_t i = 0; i < old_to_new.size(); ++i) {
      const std::uint32_t j = old_to_new[i];
      if (j != dropped && j != i) data_[j] = std::move(data_[i]);
    }
    data_.resize(new_size, Storage(default_));
  }
  void permute(std::span<const std::uint32_t> perm, std::size_t new_size) override {
    detail::permute_in_place(perm, [&](std::size_t i, std::size_t j) { std::swap(data_[i], data_[j]); });
    data_.resize(new_size, Storage(default_));
  }
  void shrink_to_fit() override { data_.shrink_to_fit(); }
  [[nodiscard]] std::unique_ptr<Base_property_array> clone() const override {
    return std::make_unique<Property_array>(*this);
  }
  [[nodiscard]] std::size_t memory_bytes() const override {
    return data_.capacity() * sizeof(Storage);
  }
  [[nodiscard]] const std::type_info& value_type() const override { return typeid(T); }

  T& operator[](std::size_t i) { return Property_storage<T>::ref(data_[i]); }
  const T& operator[](std::size_t i) const { return Property_storage<T>::ref(data_[i]); }
  [[nodiscard]] std::size_t size() const { return data_.size(); }
  [[nodiscard]] const T& default_value() const { return default_; }
  /// The raw storage (for T = bool its elements are Bool_box).
  huge_page_vector<Storage>& storage() { return data_; }
  const huge_page_vector<Storage>& storage() const { return data_; }

private:
  T default_;
  huge_page_vector<Storage> data_; // big ones on huge pages (memory/huge_pages.h)
};

/// A typed handle to one property array, indexed by Key (an index type with
/// .idx()). Cheap to copy; valid until the property is removed or its mesh
/// destroyed. A default-constructed handle is null (operator bool false).
/// Models a boost lvalue property map (get/put/operator[]); get returns T&.
template <class Key, class T>
class Property_map : public boost::put_get_helper<T&, Property_map<Key, T>> {
public:
  using key_type = Key;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;

  Property_map() = default;
  explicit Property_map(Property_array<T>* a) : array_(a) {}

  T& operator[](Key k) const { return (*array_)[k.idx()]; }
  explicit operator bool() const { return array_ != nullptr; }
  [[nodiscard]] const std::string& name() const { return array_->name(); }
  [[nodiscard]] std::size_t size() const { return array_->size(); }
  /// The underlying array (for whole-array work; bool is stored as Bool_box).
  Property_array<T>& array() const { return *array_; }

  friend bool operator==(const Property_map& a, const Property_map& b) { return a.array_ == b.array_; }
  // get(m, k) and put(m, k, v) come from boost::put_get_helper (found by ADL).

private:
  template <class>
  friend class Property_container;
  Property_array<T>* array_ = nullptr;
};

/// All property arrays of one element kind, kept at one common size.
template <class Key>
class Property_container {
public:
  Property_container() = default;
  Property_container(const Property_container& o) : size_(o.size_), anonymous_(o.anonymous_) {
    arrays_.reserve(o.arrays_.size());
    for (const auto& a : o.arrays_) arrays_.push_back(a->clone());
  }
  Property_container& operator=(const Property_container& o) {
    if (this != &o) {
      Property_container tmp(o);
      *this = std::move(tmp);
    }
    return *this;
  }
  Property_container(Property_container&&) noexcept = default;
  Property_container& operator=(Property_container&&) noexcept = default;
  ~Property_container() = default;

  /// Adds a property; an empty name makes it anonymous (never found by name).
  /// Returns null if a property of that name already exists.
  template <class T>
  Property_map<Key, T> add(std::string name, T default_value) {
    if (!name.empty() && find_array(name) != nullptr) return {};
    if (name.empty()) name = "\x01" "anonymous:" + std::to_string(anonymous_++);
    auto a = std::make_unique<Property_array<T>>(std::move(name), std::move(default_value), size_);
    Property_array<T>* p = a.get();
    arrays_.push_back(std::move(a));
    return Property_map<Key, T>(p);
  }

  /// The property of that name and value type T, if any.
  template <class T>
  std::optional<Property_map<Key, T>> get(std::string_view name) const {
    Base_property_array* a = find_array(name);
    if (a == nullptr || a->value_type() != typeid(T)) return std::nullopt;
    return Property_map<Key, T>(static_cast<Property_array<T>*>(a));
  }

  [[nodiscard]] bool exists(std::string_view name) const { return find_array(name) != nullptr; }

  /// Removes the property; returns false if it is not (or no longer) here.
  template <class T>
  bool remove(Property_map<Key, T>& m) {
    for (auto it = arrays_.begin(); it != arrays_.end(); ++it) {
      if (it->get() == m.array_) {
        arrays_.erase(it);
        m.array_ = nullptr;
        return true;
      }
    }
    return false;
  }

  /// Names of the named properties, in creation order.
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& a : arrays_)
      if (a->name().empty() || a->name()[0] != '\x01') out.push_back(a->name());
    return out;
  }
  [[nodiscard]] std::size_t n_properties() const { return arrays_.size(); }

  [[nodiscard]] std::size_t size() const { return size_; }
  void reserve(std::size_t n) {
    for (auto& a : arrays_) a->reserve(n);
  }
  void resize(std::size_t n) {
    for (auto& a : arrays_) a->resize(n);
    size_ = n;
  }
  void push_back() {
    for (auto& a : arrays_) a->push_back();
    ++size_;
  }
  void reset(std::size_t i) {
    for (auto& a : arrays_) a->reset(i);
  }
  void compact(std::span<const std::uint32_t> old_to_new, std::size_t new_size) {
    for (auto& a : arrays_) a->compact(old_to_new, new_size);
    size_ = new_size;
  }
  void permute(std::span<const std::uint32_t> perm, std::size_t new_size) {
    for (auto& a : arrays_) a->permute(perm, new_size);
    size_ = new_size;
  }
  void shrink_to_fit() {
    for (auto& a : arrays_) a->shrink_to_fit();
  }
  /// Removes every property and sets the size to 0.
  void clear() {
    arrays_.clear();
    size_ = 0;
  }
  [[nodiscard]] std::size_t memory_bytes() const {
    std::size_t b = 0;
    for (const auto& a : arrays_) b += a->memory_bytes();
    return b;
  }

private:
  Base_property_array* find_array(std::string_view name) const {
    for (const auto& a : arrays_)
      if (a->name() == name) return a.get();
    return nullptr;
  }

  std::vector<std::unique_ptr<Base_property_array>> arrays_;
  std::size_t size_ = 0;
  std::size_t anonymous_ = 0;
};

} // namespace genmesh::detail
