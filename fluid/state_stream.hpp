#pragma once
// A run's state as bytes, for checkpoints (tools/checkpoint.hpp): each class that holds state the step needs writes
// its own fields in a fixed order and reads them back in the same order. Values are stored as their bytes (the
// same machine and build read them), so a restored double is the same double, bit for bit.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace slide {

// Numbers, codes, fixed-size Eigen vectors of doubles (stored as their coefficients) and arrays of those. Not structs:
// their padding bytes are whatever the memory held, so a checkpoint of the same state would not be the same bytes
// (found when checkpoints from several processes were compared with one process's); a struct lists its fields.
template <class T>
concept FixedVector = requires { T::SizeAtCompileTime; typename T::Scalar; } && std::is_same_v<typename T::Scalar, double>;
template <class T>
struct IsPlainArray : std::false_type {};
template <class T, std::size_t N>
struct IsPlainArray<std::array<T, N>> : std::bool_constant<std::is_arithmetic_v<T> || std::is_enum_v<T>> {};
template <class T>
concept StateValue = std::is_arithmetic_v<T> || std::is_enum_v<T> || FixedVector<T> || IsPlainArray<T>::value;

class StateWriter {
 public:
  template <StateValue T>
  void put(const T& value) {
    if constexpr (FixedVector<T>) {
      for (int k = 0; k < T::SizeAtCompileTime; ++k) put(value[k]);
    } else {
      const auto* p = reinterpret_cast<const char*>(&value);
      bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
  }
  template <StateValue T>
  void put(const std::vector<T>& values) {
    put<std::uint64_t>(values.size());
    for (const T& v : values) put(v);
  }
  void put(const std::string& text) {
    put<std::uint64_t>(text.size());
    bytes_.insert(bytes_.end(), text.begin(), text.end());
  }
  // Bytes as they are, without a length (a section whose length the stream says before it).
  void append(const void* data, std::size_t n) {
    const auto* p = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), p, p + n);
  }
  // The same name as StateReader::io, so that one template lists a type's fields for both directions.
  template <class T>
  void io(const T& value) {
    put(value);
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class StateReader {
 public:
  explicit StateReader(const std::vector<char>& bytes) : bytes_(bytes) {}

  template <StateValue T>
  void get(T& value) {
    if constexpr (FixedVector<T>) {
      for (int k = 0; k < T::SizeAtCompileTime; ++k) get(value[k]);
    } else {
      take(&value, sizeof(T));
    }
  }
  template <StateValue T>
  void get(std::vector<T>& values) {
    std::uint64_t n = 0;
    get(n);
    if (n > (bytes_.size() - at_) / std::max<std::size_t>(1, sizeof(T))) throw std::runtime_error("the state is truncated");
    values.resize(n);
    for (T& v : values) get(v);
  }
  void get(std::string& text) {
    std::uint64_t n = 0;
    get(n);
    if (n > bytes_.size() - at_) throw std::runtime_error("the state is truncated");
    text.assign(bytes_.data() + at_, n);
    at_ += n;
  }
  template <StateValue T>
  T get() {
    T value{};
    get(value);
    return value;
  }
  template <class T>
  void io(T& value) {
    get(value);
  }
  bool at_end() const { return at_ == bytes_.size(); }
  // The next n bytes as they are (StateWriter::append), in place.
  const unsigned char* take_bytes(std::size_t n) {
    if (n > bytes_.size() - at_) throw std::runtime_error("the state is truncated");
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + at_);
    at_ += n;
    return p;
  }
  std::size_t remaining() const { return bytes_.size() - at_; }

 private:
  void take(void* out, std::size_t n) {
    if (n > bytes_.size() - at_) throw std::runtime_error("the state is truncated");
    if (n) std::memcpy(out, bytes_.data() + at_, n);
    at_ += n;
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

}  // namespace slide
