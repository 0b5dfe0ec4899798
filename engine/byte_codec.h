#pragma once
// The bytes a task, a reference or an outcome travels as between processes (MPI ranks): numbers
// raw in little-endian order, strings and vectors prefixed by their length. Both ends run the
// same build, so the format has no version; a truncated or overlong message throws.

#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace shockmap {

static_assert(std::endian::native == std::endian::little, "the byte codec writes host order");

class ByteWriter {
 public:
  template <typename T>
  requires std::is_arithmetic_v<T>
  void Put(T v) { Raw(&v, sizeof v); }
  void Put(std::string_view s) {
    Put(static_cast<std::uint64_t>(s.size()));
    Raw(s.data(), s.size());
  }
  void Put(const std::string& s) { Put(std::string_view(s)); }
  void Put(const std::vector<double>& v) {
    Put(static_cast<std::uint64_t>(v.size()));
    Raw(v.data(), v.size() * sizeof(double));
  }
  template <typename T>
  void Put(const std::optional<T>& v) {
    Put(static_cast<std::uint8_t>(v.has_value()));
    if (v) Put(*v);
  }

  const std::string& Bytes() const { return bytes_; }
  std::string Take() { return std::move(bytes_); }

 private:
  void Raw(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}

  template <typename T>
  requires std::is_arithmetic_v<T> T Get() {
    T v;
    std::memcpy(&v, Take(sizeof v), sizeof v);
    return v;
  }
  std::string GetString() {
    const auto n = Count(1);
    return std::string(Take(n), n);
  }
  std::vector<double> GetDoubles() {
    const auto n = Count(sizeof(double));
    std::vector<double> v(n);
    if (n > 0) std::memcpy(v.data(), Take(n * sizeof(double)), n * sizeof(double));
    return v;
  }
  template <typename T>
  std::optional<T> GetOptional() {
    if (Get<std::uint8_t>() == 0) return std::nullopt;
    return Get<T>();
  }
  // Reads into `v` what ByteWriter::Put(v) wrote, by v's type.
  template <typename T>
  requires std::is_arithmetic_v<T>
  void Read(T& v) { v = Get<T>(); }
  void Read(std::string& v) { v = GetString(); }
  void Read(std::vector<double>& v) { v = GetDoubles(); }
  template <typename T>
  void Read(std::optional<T>& v) {
    if (Get<std::uint8_t>() == 0) {
      v.reset();
    } else {
      Read(v.emplace());
    }
  }
  bool AtEnd() const { return at_ == bytes_.size(); }
  // Throws unless every byte was read.
  void ExpectEnd() const {
    if (!AtEnd()) throw std::runtime_error("message: trailing bytes");
  }

 private:
  std::size_t Count(std::size_t element_size) {
    const auto n = Get<std::uint64_t>();
    if (n > (bytes_.size() - at_) / element_size) throw std::runtime_error("message: truncated");
    return static_cast<std::size_t>(n);
  }
  const char* Take(std::size_t n) {
    if (n > bytes_.size() - at_) throw std::runtime_error("message: truncated");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace shockmap
