#include "io/digest/digest.h"

#include <openssl/evp.h>

#include <cstdio>
#include <stdexcept>

#include "io/format_error.h"

// The whole of xxHash in this file (header-only mode): no shared library to load at
// start-up, and the hashing loop inlined.
#define XXH_INLINE_ALL
#include <xxhash.h>

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
  DigestKind kind;
  EVP_MD_CTX* sha = nullptr;
  XXH3_state_t* xxh = nullptr;
  explicit State(DigestKind k) : kind(k) {
    if (kind == DigestKind::sha256) {
      sha = EVP_MD_CTX_new();
      if (!sha || EVP_DigestInit_ex(sha, EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("SHA-256 is not available from libcrypto");
    } else {
      xxh = XXH3_createState();
      if (!xxh || XXH3_128bits_reset(xxh) != XXH_OK) throw std::runtime_error("XXH3-128: cannot start a digest");
    }
  }
  ~State() {
    EVP_MD_CTX_free(sha);
    XXH3_freeState(xxh);
  }
  State(const State&) = delete;
  State& operator=(const State&) = delete;
};

Digest::Digest(DigestKind kind) : state_(std::make_unique<State>(kind)) {}
Digest::~Digest() = default;
Digest::Digest(Digest&&) noexcept = default;
Digest& Digest::operator=(Digest&&) noexcept = default;

void Digest::add_bytes(const void* data, std::size_t size) {
  if (size == 0) return;
  if (state_->kind == DigestKind::sha256) {
    if (EVP_DigestUpdate(state_->sha, data, size) != 1) throw std::runtime_error("SHA-256 update failed");
  } else if (XXH3_128bits_update(state_->xxh, data, size) != XXH_OK) {
    throw std::runtime_error("XXH3-128 update failed");
  }
}

std::string Digest::hex() {
  if (state_->kind == DigestKind::sha256) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(state_->sha, digest, &length) != 1) throw std::runtime_error("SHA-256 final failed");
    return hex_of(digest, length);
  }
  XXH128_canonical_t canonical;
  XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state_->xxh));
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
