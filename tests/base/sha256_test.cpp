#include "fogdrift/base/sha256.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

// FIPS 180-4 examples (NIST CSRC "SHA256.pdf") and the empty message.
TEST(Sha256, MatchesTheStandardsExamples) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, FilesHashLikeTheirBytes) {
  test::TempDir dir;
  std::string text;
  for (int i = 0; i < 70000; ++i) text.push_back(static_cast<char>(i * 31 % 251));
  test::write_file(dir / "a.bin", text);
  EXPECT_EQ(sha256_file_hex(dir / "a.bin"), sha256_hex(text));
  EXPECT_THROW(sha256_file_hex(dir / "missing.bin"), InputError);
}

}  // namespace
}  // namespace fogdrift
