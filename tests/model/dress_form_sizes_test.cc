// The dress form in three sizes and its catalogue, resources/forms/forms.json,
// which the workbench lists the forms from: each form's bust, waist and hip
// girths, measured here independently of make_dress_form.py as what a tape
// around the mesh reads (the perimeter of the mesh's cross-section by the
// plane z = the stated level, from the OBJ file itself), are the stated ones
// to their rounding to 0.1 cm; the sizes grow small < medium < large in all
// three girths; and each form is as tall as stated, to 1 mm. A regenerated or
// hand-edited form whose numbers no longer match the catalogue fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::array<const char*, 3> kMeasures = {"bust", "waist", "hip"};
constexpr std::array<const char*, 3> kSizes = {"small", "medium", "large"};
// Half the last stated digit (0.1 cm), and a margin for rounding in doubles.
constexpr double kRounding = 0.0005 + 1e-9;

fs::path FormsDir() {
  return test::SourceDir() / "resources" / "forms";
}

struct Mesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;  // 0-based
};

// `v x y z` and `f a b c` (1-based) lines; everything else is skipped.
void ReadObj(const fs::path& file, Mesh* mesh) {
  std::ifstream in(file);
  ASSERT_TRUE(in) << file;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "v") {
      std::array<double, 3> v;
      ASSERT_TRUE(words >> v[0] >> v[1] >> v[2]) << line;
      mesh->vertices.push_back(v);
    } else if (keyword == "f") {
      std::array<int, 3> f;
      ASSERT_TRUE(words >> f[0] >> f[1] >> f[2]) << line;
      for (int& i : f) {
        ASSERT_GE(i, 1) << line;
        --i;
      }
      mesh->triangles.push_back(f);
    }
  }
  ASSERT_FALSE(mesh->triangles.empty()) << file;
  for (const auto& f : mesh->triangles)
    for (int i : f) ASSERT_LT(i, static_cast<int>(mesh->vertices.size())) << file;
}

// "80.2 cm" in metres.
double Centimetres(const json& quantity) {
  std::istringstream words(quantity.get<std::string>());
  double value;
  std::string unit;
  if (!(words >> value >> unit) || unit != "cm") {
    ADD_FAILURE() << "not a length in cm: " << quantity;
    return std::numeric_limits<double>::quiet_NaN();
  }
  return value / 100;
}

// The perimeter of the cross-section by the plane z = level: the sum of the
// segments the plane cuts from the triangles. A vertex on the plane counts as
// above it, so a closed mesh gives closed cross-sections wherever it is cut.
double Girth(const Mesh& mesh, double level) {
  double total = 0;
  for (const auto& triangle : mesh.triangles) {
    std::vector<std::array<double, 2>> cut;
    for (int k = 0; k < 3; ++k) {
      const auto& a = mesh.vertices[triangle[k]];
      const auto& b = mesh.vertices[triangle[(k + 1) % 3]];
      const double da = a[2] - level, db = b[2] - level;
      if ((da >= 0) != (db >= 0)) {
        const double s = da / (da - db);
        cut.push_back({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])});
      }
    }
    if (cut.size() == 2) total += std::hypot(cut[1][0] - cut[0][0], cut[1][1] - cut[0][1]);
  }
  return total;
}

struct Form {
  json entry;
  Mesh mesh;
};

// The catalogue's forms, each with its mesh, by size.
void ReadCatalogue(std::map<std::string, Form>* forms) {
  std::ifstream in(FormsDir() / "forms.json");
  ASSERT_TRUE(in);
  const json catalogue = json::parse(in);
  ASSERT_EQ(catalogue.at("drape_forms"), 1);
  for (const json& entry : catalogue.at("forms")) {
    const std::string size = entry.at("size");
    SCOPED_TRACE(size);
    ASSERT_EQ(forms->count(size), 0u) << "size listed twice";
    Form& form = (*forms)[size];
    form.entry = entry;
    ASSERT_NO_FATAL_FAILURE(ReadObj(FormsDir() / entry.at("file").get<std::string>(), &form.mesh));
  }
  for (const char* size : kSizes) ASSERT_EQ(forms->count(size), 1u) << size;
}

TEST(DressFormSizes, GirthsAtTheStatedLevelsAreTheStatedOnes) {
  std::map<std::string, Form> forms;
  ASSERT_NO_FATAL_FAILURE(ReadCatalogue(&forms));
  for (const auto& [size, form] : forms) {
    for (const char* measure : kMeasures) {
      SCOPED_TRACE(size + " " + measure);
      const double level = Centimetres(form.entry.at("levels").at(measure));
      const double stated = Centimetres(form.entry.at(measure));
      EXPECT_NEAR(Girth(form.mesh, level), stated, kRounding) << "at z = " << level << " m";
    }
  }
}

TEST(DressFormSizes, GrowFromSmallToLarge) {
  std::map<std::string, Form> forms;
  ASSERT_NO_FATAL_FAILURE(ReadCatalogue(&forms));
  for (const char* measure : kMeasures) {
    SCOPED_TRACE(measure);
    std::array<double, 3> girths;
    for (int k = 0; k < 3; ++k) {
      const Form& form = forms.at(kSizes[k]);
      girths[k] = Girth(form.mesh, Centimetres(form.entry.at("levels").at(measure)));
    }
    EXPECT_LT(girths[0], girths[1]);
    EXPECT_LT(girths[1], girths[2]);
  }
}

TEST(DressFormSizes, AreAsTallAsStated) {
  std::map<std::string, Form> forms;
  ASSERT_NO_FATAL_FAILURE(ReadCatalogue(&forms));
  for (const auto& [size, form] : forms) {
    SCOPED_TRACE(size);
    const auto [low, high] = std::minmax_element(
        form.mesh.vertices.begin(), form.mesh.vertices.end(), [](const auto& a, const auto& b) {
          return a[2] < b[2];
        });
    EXPECT_NEAR((*high)[2] - (*low)[2], Centimetres(form.entry.at("height")), 0.001);
  }
}

}  // namespace
}  // namespace drape
