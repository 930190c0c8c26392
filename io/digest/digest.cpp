#include "io/digest/digest.h"

// SHA-256 through libcrypto's EVP interface (OpenSSL 3).
#include <openssl/evp.h>

#include <cstdio>
#include <stdexcept>

#include "io/format_error.h"
#include "io/input_file.h"

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
  struct FreeEvp {
    void operator()(EVP_MD_CTX* x) const { EVP_MD_CTX_free(x); }
  };
  DigestKind kind;
  std::unique_ptr<EVP_MD_CTX, FreeEvp> sha;   // (both freed even when the constructor throws)
  std::unique_ptr<XXH3_state_t, FreeXxh> xxh;
  explicit State(DigestKind k) : kind(k) {
    if (kind == DigestKind::sha256) {
      sha.reset(EVP_MD_CTX_new());
      if (!sha || EVP_DigestInit_ex(sha.get(), EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("SHA-256: cannot start a digest");
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
    if (EVP_DigestUpdate(state_->sha.get(), data, size) != 1) throw std::runtime_error("SHA-256 update failed");
  } else if (XXH3_128bits_update(state_->xxh.get(), data, size) != XXH_OK) {
    throw std::runtime_error("XXH3-128 update failed");
  }
}

std::string Digest::hex() {
  if (state_->kind == DigestKind::sha256) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(state_->sha.get(), digest, &length) != 1) throw std::runtime_error("SHA-256 final failed");
    return hex_of(digest, length);
  }
  XXH128_canonical_t canonical;
  XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state_->xxh.get()));
  return hex_of(canonical.digest, sizeof canonical.digest);
}

std::string sha256_of_file(const std::string& path) {
  require_regular_file(path);
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
