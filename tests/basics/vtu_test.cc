// The VTU writer: every array reads back, through its base64 byte count, as the values written
// (VTK XML format, "binary" inline arrays: a UInt32 byte count and the data, encoded apart).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "vtu.h"

using namespace pumpd;

namespace
{
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
        const std::string header = decode(body.substr(0, 8)); // 4 bytes: 8 characters with padding
        std::uint32_t     bytes;
        std::memcpy(&bytes, header.data(), 4);
        const std::string data = decode(body.substr(8));
        EXPECT_EQ(bytes, data.size()) << key;
        found[key] = data;
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
  write_vtu("vtu_test.vtu", grid);

  const auto a = arrays("vtu_test.vtu");
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

TEST(Vtu, AFieldOfTheWrongLengthIsRefused)
{
  VtuGrid grid;
  grid.points = {0., 0., 1., 0., 1., 1.};
  grid.add_cell(0, 3, 5);
  grid.cell_data.push_back({"stress", 3, {1., 2.}});
  EXPECT_THROW(write_vtu("vtu_test_bad.vtu", grid), std::logic_error);
}
