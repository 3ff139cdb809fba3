#include "ui/widgets/typed_json.h"

#include <gtest/gtest.h>

namespace drape {
namespace {

TEST(TypedJson, NumbersStayNumbersAndQuantitiesGoToTheReader) {
  EXPECT_EQ(TypedQuantity(" 0.5 "), nlohmann::json(0.5));
  EXPECT_EQ(TypedQuantity("-2e-3"), nlohmann::json(-2e-3));
  EXPECT_EQ(TypedQuantity(" 5 cm"), nlohmann::json("5 cm"));
  EXPECT_EQ(TypedList("1 cm, 0,2"), (nlohmann::json{"1 cm", 0.0, 2.0}));
  EXPECT_EQ(TypedLists("0, 0; 10 cm, 0;"),
            (nlohmann::json{nlohmann::json{0.0, 0.0}, nlohmann::json{"10 cm", 0.0}}));
  // Not judged here: the reader says what is wrong with "x".
  EXPECT_EQ(TypedList("x"), (nlohmann::json{"x"}));
}

}  // namespace
}  // namespace drape
