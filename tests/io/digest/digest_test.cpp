// The two digests against values from independent implementations: FIPS 180-2's
// SHA-256 example, xxHash's own sanity vector for XXH3-128 of nothing, and Python's
// hashlib and xxhash (python3-xxhash) for the rest, computed once with
//   hashlib.sha256(b).hexdigest(), xxhash.xxh3_128_hexdigest(b)
// with b = b'abc' and b = bytes(range(256)) * 5 (1,280 bytes: xxHash's long-input path).

#include <gtest/gtest.h>

#include <vector>

#include "io/digest/digest.h"

namespace gesmi::io {
namespace {

std::string digest_of(DigestKind kind, const std::vector<unsigned char>& bytes, std::size_t chunk) {
  Digest h(kind);
  for (std::size_t at = 0; at < bytes.size(); at += chunk)
    h.add_bytes(bytes.data() + at, std::min(chunk, bytes.size() - at));
  return h.hex();
}

std::vector<unsigned char> long_input() {
  std::vector<unsigned char> bytes(1280);
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i % 256);
  return bytes;
}

TEST(Digest, Sha256MatchesTheStandardAndHashlib) {
  const std::vector<unsigned char> abc = {'a', 'b', 'c'};
  EXPECT_EQ(digest_of(DigestKind::sha256, abc, 3), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(digest_of(DigestKind::sha256, {}, 1), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Digest, Xxh128MatchesXxhashInItsCanonicalOrder) {
  EXPECT_EQ(digest_of(DigestKind::xxh128, {}, 1), "99aa06d3014798d86001c324468d497f");
  EXPECT_EQ(digest_of(DigestKind::xxh128, {'a', 'b', 'c'}, 3), "06b05ab6733a618578af5f94892f3950");
  EXPECT_EQ(digest_of(DigestKind::xxh128, long_input(), long_input().size()), "d92ab3a1cb0542a74844b009e164352e");
}

TEST(Digest, PiecesDigestAsTheWhole) {
  // Streaming: however the bytes are cut, the digest is that of the whole.
  const std::vector<unsigned char> bytes = long_input();
  for (const DigestKind kind : {DigestKind::sha256, DigestKind::xxh128}) {
    const std::string whole = digest_of(kind, bytes, bytes.size());
    for (const std::size_t chunk : {1u, 7u, 64u, 239u, 241u, 1000u}) EXPECT_EQ(digest_of(kind, bytes, chunk), whole) << chunk;
  }
}

TEST(Digest, ArraysAreLengthPrefixed) {
  // {1, 2} then {3} differs from {1} then {2, 3}: each array carries its length.
  const auto of = [](std::vector<double> a, std::vector<double> b) {
    Digest h(DigestKind::xxh128);
    h.add(a);
    h.add(b);
    return h.hex();
  };
  EXPECT_NE(of({1.0, 2.0}, {3.0}), of({1.0}, {2.0, 3.0}));
  EXPECT_EQ(of({1.0, 2.0}, {3.0}), of({1.0, 2.0}, {3.0}));
}

TEST(Digest, NamesAndTitles) {
  EXPECT_STREQ(digest_name(DigestKind::sha256), "sha256");
  EXPECT_STREQ(digest_name(DigestKind::xxh128), "xxh128");
  EXPECT_STREQ(digest_title(DigestKind::xxh128), "XXH3-128");
}

}  // namespace
}  // namespace gesmi::io
