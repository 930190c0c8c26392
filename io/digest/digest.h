#pragma once
// The digests gesmi computes, behind one interface:
// - SHA-256 (OpenSSL's libcrypto): the provenance of input files, which anyone can
//   check with `sha256sum`, and the integrity digests of result files of formats 2 to 5;
// - XXH3-128 (xxHash, compiled in from its header; `xxhsum -H2` prints it as XXH128):
//   the integrity digests of result files from format 6 and the mission fingerprints
//   they store. It is about nine times faster here (docs/performance.md), and what
//   those digests guard against, a file changed after gesmi wrote it, needs no
//   cryptographic hash: neither hash stops someone who recomputes the digests on
//   purpose (docs/guarantees.md).
//
//   Digest h(DigestKind::xxh128);
//   h.add(std::span<const double>(values));
//   std::string hex = h.hex();   // lowercase hex digits; finishes the digest

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gesmi::io {

enum class DigestKind { sha256, xxh128 };

/// "sha256" or "xxh128": how result files name the digests of that kind.
const char* digest_name(DigestKind kind);
/// "SHA-256" or "XXH3-128": how messages name it.
const char* digest_title(DigestKind kind);

class Digest {
 public:
  explicit Digest(DigestKind kind);
  ~Digest();
  Digest(Digest&&) noexcept;
  Digest& operator=(Digest&&) noexcept;

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

  /// Finishes and returns the digest as hex (64 digits for SHA-256, 32 for XXH3-128,
  /// in the canonical big-endian order `xxhsum` and Python's xxhash print); the object
  /// is spent.
  std::string hex();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// SHA-256 of a whole file as hex; FormatError naming the file when it cannot be read.
std::string sha256_of_file(const std::string& path);

}  // namespace gesmi::io
