// The path OBJ file of `knots saddles`: written and read back exactly, and a
// file that is not one is refused with InputError naming it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ek/core/errors.hpp"
#include "ek/transitions/saddles.hpp"

using namespace ek;

namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("ek_path_io_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + name)).string();
}

}  // namespace

TEST(PathObj, RoundTripIsExact) {
  std::vector<Points> images;
  std::vector<double> energies;
  for (int k = 0; k < 3; ++k) {
    images.push_back(Points::Random(5 + k, 3));
    energies.push_back(1.0 / (3.0 + k));
  }
  const std::string file = temp_path("round.obj");
  write_path_obj(file, images, energies);
  std::vector<double> read_energies;
  const std::vector<Points> read = read_path_obj(file, read_energies);
  std::filesystem::remove(file);
  ASSERT_EQ(read.size(), images.size());
  ASSERT_EQ(read_energies.size(), energies.size());
  for (size_t k = 0; k < images.size(); ++k) {
    EXPECT_EQ(read[k], images[k]) << "image " << k;
    EXPECT_EQ(read_energies[k], energies[k]) << "image " << k;
  }
}

TEST(PathObj, RefusesAFileWithoutImagesOrEnergies) {
  const std::string file = temp_path("bad.obj");
  {
    std::ofstream out(file);
    out << "v 0 0 0\nv 1 0 0\n";
  }
  std::vector<double> e;
  EXPECT_THROW(read_path_obj(file, e), InputError);
  {
    std::ofstream out(file);
    out << "o image_0 E=abc\nv 0 0 0\n";
  }
  EXPECT_THROW(read_path_obj(file, e), InputError);
  std::filesystem::remove(file);
  EXPECT_THROW(read_path_obj(file, e), InputError);
  EXPECT_THROW(write_path_obj(file, {Points::Zero(4, 3)}, {}), std::exception);
}
