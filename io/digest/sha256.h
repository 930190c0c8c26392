#pragma once
// SHA-256 through OpenSSL's libcrypto (EVP interface): the one digest gesmi uses
// for input fingerprints and for the integrity of result files.
//
//   Sha256 h;
//   h.add(std::span<const double>(values));
//   std::string hex = h.hex();   // 64 lowercase hex digits; finishes the digest

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gesmi::io {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(Sha256&&) noexcept;
  Sha256& operator=(Sha256&&) noexcept;

  /// Adds raw bytes.
  void add_bytes(const void* data, std::size_t size);
  /// Adds an array of trivially copyable values, preceded by its length so that
  /// two arrays that differ only in where one ends and the next starts differ.
  template <class T>
  void add(std::span<const T> values) {
    add_count(values.size());
    add_bytes(values.data(), values.size_bytes());
  }
  template <class T>
  void add(const std::vector<T>& values) {
    add(std::span<const T>(values));
  }
  void add(std::string_view text) {
    add_count(text.size());
    add_bytes(text.data(), text.size());
  }
  void add(double x) { add_bytes(&x, sizeof x); }
  void add_count(std::uint64_t n) { add_bytes(&n, sizeof n); }

  /// Finishes and returns the digest as 64 hex digits (the object is spent).
  std::string hex();

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

/// SHA-256 of a whole file as hex; FormatError naming the file when it cannot be read.
std::string sha256_of_file(const std::string& path);

}  // namespace gesmi::io
