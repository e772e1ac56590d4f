#include <catch2/catch.hpp>

#include <sstream>

#include "perception/service/device_registry.h"

using namespace alplan::perception::service;

namespace {

std::string refusal(const std::string& text) {
  std::istringstream in(text);
  try {
    read_device_registry(in, "tokens.txt");
  } catch (const DeviceRegistryError& e) {
    return e.what();
  }
  FAIL("accepted: " << text);
  return {};
}

}  // namespace

TEST_CASE("a tokens file: devices, tokens and seniors, comments and blank lines skipped") {
  std::istringstream in(
      "# device token senior\n"
      "\n"
      "wb-01  0123456789abcdef0123   alice\r\n"
      "\twb-02\tAbC.def_ghi~jkl+mno/p= bob  \n"
      "   # indented comment\n");
  const DeviceRegistry registry = read_device_registry(in, "tokens.txt");
  REQUIRE(registry.size() == 2);
  CHECK(registry.devices()[0].id == "wb-01");
  CHECK(registry.devices()[0].senior == "alice");
  CHECK(registry.devices()[1].token == "AbC.def_ghi~jkl+mno/p=");
  CHECK(registry.authenticate("0123456789abcdef0123")->id == "wb-01");
  CHECK(registry.authenticate("AbC.def_ghi~jkl+mno/p=")->senior == "bob");
  CHECK(registry.authenticate("0123456789abcdef012") == nullptr);   // a prefix
  CHECK(registry.authenticate("0123456789abcdef01234") == nullptr);  // longer
  CHECK(registry.authenticate("") == nullptr);
  CHECK(registry.find("wb-02")->senior == "bob");
  CHECK(registry.find("wb-03") == nullptr);

  std::ostringstream out;
  write_device_registry(out, registry);
  std::istringstream back(out.str());
  CHECK(read_device_registry(back, "again").devices()[1].token == registry.devices()[1].token);
}

TEST_CASE("a bad tokens file is refused naming the line and the problem") {
  CHECK(refusal("wb-01 0123456789abcdef alice\nwb-02 short bob\n") ==
        "tokens.txt:2: error: token too short (need at least 16 characters)");
  CHECK(refusal("wb-01 0123456789abcdef\n") == "tokens.txt:1: error: expected: device token senior");
  CHECK(refusal("wb-01 0123456789abcdef alice extra\n") == "tokens.txt:1: error: unexpected fourth field 'extra'");
  CHECK(refusal("wb!01 0123456789abcdef alice\n") == "tokens.txt:1: error: device id 'wb!01' must be 1-32 of [A-Za-z0-9._-]");
  CHECK(refusal("wb-01 0123456789abcdef\"x alice\n") == "tokens.txt:1: error: token may hold only [A-Za-z0-9._~+/=-]");
  CHECK(refusal("wb-01 0123456789abcdef al!ce\n") == "tokens.txt:1: error: senior 'al!ce' must be 1-64 of [A-Za-z0-9._-]");
  CHECK(refusal("wb-01 0123456789abcdef a\nwb-01 0123456789abcdeX b\n") ==
        "tokens.txt:2: error: device 'wb-01' is listed twice");
  CHECK(refusal("wb-01 0123456789abcdef a\nwb-02 0123456789abcdef b\n") ==
        "tokens.txt:2: error: this token is already another device's");
  CHECK_THROWS_WITH(read_device_registry_file("/no/such/tokens.txt"),
                    "/no/such/tokens.txt: error: cannot open the file");
}

TEST_CASE("token comparison: equal only for equal length and bytes") {
  CHECK(tokens_equal("abcdefgh", "abcdefgh"));
  CHECK_FALSE(tokens_equal("abcdefgh", "abcdefgi"));
  CHECK_FALSE(tokens_equal("abcdefgh", "bbcdefgh"));
  CHECK_FALSE(tokens_equal("abcdefgh", "abcdefg"));
  CHECK_FALSE(tokens_equal("abc", std::string("abc\0", 4)));
  CHECK(tokens_equal("", ""));
}
