#include "io/digest/digest.h"

// SHA-256 from libcrypto's low-level interface, which OpenSSL 3 keeps but marks
// deprecated in favour of EVP. EVP's first fetch of SHA-256 starts the default provider:
// 1.2-1.4 ms of CPU per process here, against 3 ms to hash a 5.8 MB mission, for the
// same code (the SHA extensions, sha256_block_data_order_shaext) and the same digests
// (docs/performance.md, "SHA-256 without EVP's provider start").
#define OPENSSL_SUPPRESS_DEPRECATED
#include <openssl/sha.h>
#if defined(OPENSSL_NO_DEPRECATED_3_0)
#error "gesmi needs libcrypto's SHA256_Init/Update/Final (an OpenSSL built with its 3.0 deprecations)"
#endif

#include <cstdio>
#include <stdexcept>

#include "io/format_error.h"

// The whole of xxHash in this file (header-only mode): no shared library to load at
// start-up, and the hashing loop inlined.
#define XXH_INLINE_ALL
#include <xxhash.h>

// XXH3's output is stable from xxHash 0.8.0 on; an earlier one would compute other
// digests and refuse every result a current build wrote (and the reverse).
static_assert(XXH_VERSION_NUMBER >= 800, "gesmi needs xxHash 0.8.0 or later (XXH3-128 as stable)");

namespace gesmi::io {
namespace {

std::string hex_of(const unsigned char* bytes, std::size_t length) {
  static const char digits[] = "0123456789abcdef";
  std::string out(2 * length, '0');
  for (std::size_t i = 0; i < length; ++i) {
    out[2 * i] = digits[bytes[i] >> 4];
    out[2 * i + 1] = digits[bytes[i] & 0xf];
  }
  return out;
}

}  // namespace

const char* digest_name(DigestKind kind) { return kind == DigestKind::sha256 ? "sha256" : "xxh128"; }
const char* digest_title(DigestKind kind) { return kind == DigestKind::sha256 ? "SHA-256" : "XXH3-128"; }

struct Digest::State {
  struct FreeXxh {
    void operator()(XXH3_state_t* x) const { XXH3_freeState(x); }
  };
  DigestKind kind;
  SHA256_CTX sha{};
  std::unique_ptr<XXH3_state_t, FreeXxh> xxh;  // (freed even when the constructor throws)
  explicit State(DigestKind k) : kind(k) {
    if (kind == DigestKind::sha256) {
      if (SHA256_Init(&sha) != 1) throw std::runtime_error("SHA-256: cannot start a digest");
    } else {
      xxh.reset(XXH3_createState());
      if (!xxh || XXH3_128bits_reset(xxh.get()) != XXH_OK) throw std::runtime_error("XXH3-128: cannot start a digest");
    }
  }
};

Digest::Digest(DigestKind kind) : state_(std::make_unique<State>(kind)) {}
Digest::~Digest() = default;
Digest::Digest(Digest&&) noexcept = default;
Digest& Digest::operator=(Digest&&) noexcept = default;

void Digest::add_bytes(const void* data, std::size_t size) {
  if (size == 0) return;
  if (state_->kind == DigestKind::sha256) {
    if (SHA256_Update(&state_->sha, data, size) != 1) throw std::runtime_error("SHA-256 update failed");
  } else if (XXH3_128bits_update(state_->xxh.get(), data, size) != XXH_OK) {
    throw std::runtime_error("XXH3-128 update failed");
  }
}

std::string Digest::hex() {
  if (state_->kind == DigestKind::sha256) {
    unsigned char digest[SHA256_DIGEST_LENGTH];
    if (SHA256_Final(digest, &state_->sha) != 1) throw std::runtime_error("SHA-256 final failed");
    return hex_of(digest, sizeof digest);
  }
  XXH128_canonical_t canonical;
  XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state_->xxh.get()));
  return hex_of(canonical.digest, sizeof canonical.digest);
}

std::string sha256_of_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw FormatError(path + ": cannot open the file (does it exist?)");
  Digest h(DigestKind::sha256);
  std::vector<unsigned char> buffer(1 << 16);
  std::size_t got = 0;
  while ((got = std::fread(buffer.data(), 1, buffer.size(), file)) > 0) h.add_bytes(buffer.data(), got);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) throw FormatError(path + ": cannot read the file");
  return h.hex();
}

}  // namespace gesmi::io
