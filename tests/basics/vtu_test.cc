// The VTU writer: every array reads back, through its base64 byte count, as the values written
// (VTK XML format, "binary" inline arrays: a UInt32 byte count and the data, encoded apart); the
// encoding is RFC 4648's; a field that does not fit its grid is refused before a file is written.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vtu.h"

using namespace pumpd;

namespace
{
  std::string temporary(const std::string &name)
  {
    return (std::filesystem::temp_directory_path() / name).string();
  }

  std::string decode(const std::string &text)
  {
    std::string out;
    std::uint32_t v = 0;
    int           bits = 0;
    for (char c : text)
      {
        int d = c >= 'A' && c <= 'Z' ? c - 'A' :
                c >= 'a' && c <= 'z' ? c - 'a' + 26 :
                c >= '0' && c <= '9' ? c - '0' + 52 :
                c == '+'             ? 62 :
                c == '/'             ? 63 :
                                       -1;
        if (d < 0)
          continue;
        v = (v << 6) | std::uint32_t(d);
        bits += 6;
        if (bits >= 8)
          {
            bits -= 8;
            out += char((v >> bits) & 0xff);
          }
      }
    return out;
  }

  /// Each DataArray's bytes by its Name (Points: "Points"), checked against its byte count: the
  /// first base64 block (up to its padding) is the UInt32 count, the rest the data.
  std::map<std::string, std::string> encoded; ///< each array's data as written (base64), by name

  std::map<std::string, std::string> arrays(const std::string &file)
  {
    std::ifstream     in(file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::map<std::string, std::string> found;
    for (std::size_t at = text.find("<DataArray"); at != std::string::npos; at = text.find("<DataArray", at + 1))
      {
        const std::size_t open = text.find('>', at), close = text.find("</DataArray>", at);
        const std::string tag  = text.substr(at, open - at);
        const std::size_t name = tag.find("Name=\"");
        const std::string key  = name == std::string::npos ? "Points" : tag.substr(name + 6, tag.find('"', name + 6) - name - 6);
        EXPECT_NE(tag.find("format=\"binary\""), std::string::npos) << key;
        std::string body = text.substr(open + 1, close - open - 1);
        body.erase(0, body.find_first_not_of("\n "));
        body.erase(body.find_last_not_of("\n ") + 1);
        // 4 bytes: 8 characters, the last two padding; then the data in whole blocks of 4.
        EXPECT_EQ(body.substr(6, 2), "==") << key;
        EXPECT_EQ((body.size() - 8) % 4, 0u) << key;
        const std::string header = decode(body.substr(0, 8));
        std::uint32_t     bytes;
        std::memcpy(&bytes, header.data(), 4);
        const std::string data = decode(body.substr(8));
        EXPECT_EQ(bytes, data.size()) << key;
        found[key] = data;
        encoded[key] = body.substr(8);
      }
    return found;
  }

  template <class T>
  std::vector<T> values(const std::string &bytes)
  {
    std::vector<T> v(bytes.size() / sizeof(T));
    std::memcpy(v.data(), bytes.data(), bytes.size());
    return v;
  }
} // namespace

TEST(Vtu, EveryArrayReadsBackAsWritten)
{
  VtuGrid grid;
  grid.points = {0., 0., 1., 0., 1., 1., 0., 1., 2., 0.5};
  grid.add_cell(0, 4, 9);
  grid.add_cell(2, 3, 5);
  grid.point_data.push_back({"displacement", 3, {0.1, 0.2, 0., 1. / 3., -2e-7, 0., 5., 6., 0., 7., 8., 0., 9., 1e300, 0.}});
  grid.cell_data.push_back({"kind", 1, {3., -1.}, true});
  grid.active_vectors = "displacement";
  write_vtu(temporary("pumpd_vtu_test.vtu"), grid);

  const auto a = arrays(temporary("pumpd_vtu_test.vtu"));
  ASSERT_EQ(a.size(), 6u);
  const auto xyz = values<double>(a.at("Points"));
  ASSERT_EQ(xyz.size(), 15u);
  for (std::size_t p = 0; p < 5; ++p)
    {
      EXPECT_EQ(xyz[3 * p], grid.points[2 * p]);
      EXPECT_EQ(xyz[3 * p + 1], grid.points[2 * p + 1]);
      EXPECT_EQ(xyz[3 * p + 2], 0.);
    }
  EXPECT_EQ(values<std::int64_t>(a.at("connectivity")), (std::vector<std::int64_t>{0, 1, 2, 3, 2, 3, 4}));
  EXPECT_EQ(values<std::int64_t>(a.at("offsets")), (std::vector<std::int64_t>{4, 7}));
  EXPECT_EQ(values<std::uint8_t>(a.at("types")), (std::vector<std::uint8_t>{9, 5}));
  EXPECT_EQ(values<double>(a.at("displacement")), grid.point_data[0].values);
  EXPECT_EQ(values<std::int32_t>(a.at("kind")), (std::vector<std::int32_t>{3, -1}));
}

TEST(Vtu, AFieldOfTheWrongLengthIsRefusedBeforeTheFileIsWritten)
{
  std::filesystem::remove(temporary("pumpd_vtu_test_bad.vtu"));
  VtuGrid grid;
  grid.points = {0., 0., 1., 0., 1., 1.};
  grid.add_cell(0, 3, 5);
  grid.cell_data.push_back({"stress", 3, {1., 2.}});
  EXPECT_THROW(write_vtu(temporary("pumpd_vtu_test_bad.vtu"), grid), std::logic_error);
  grid.cell_data = {{"kind", 1, {0.5}, true}};
  EXPECT_THROW(write_vtu(temporary("pumpd_vtu_test_bad.vtu"), grid), std::logic_error);
  grid.cell_data = {{"none", 0, {}}};
  EXPECT_THROW(write_vtu(temporary("pumpd_vtu_test_bad.vtu"), grid), std::logic_error);
  EXPECT_FALSE(std::filesystem::exists(temporary("pumpd_vtu_test_bad.vtu")));
}

// RFC 4648's test vectors: "f", "fo", "foo" as cell types (one byte each) of one, two and three
// vertex cells.
TEST(Vtu, Base64AsRfc4648)
{
  for (const auto &[text, expected] : std::vector<std::pair<std::string, std::string>>{
         {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}})
    {
      VtuGrid grid;
      for (char c : text)
        {
          grid.points.insert(grid.points.end(), {0., 0.});
          grid.add_cell(std::int64_t(grid.n_points() - 1), 1, std::uint8_t(c));
        }
      write_vtu(temporary("pumpd_vtu_test_rfc.vtu"), grid);
      arrays(temporary("pumpd_vtu_test_rfc.vtu"));
      EXPECT_EQ(encoded.at("types"), expected) << text;
    }
}
