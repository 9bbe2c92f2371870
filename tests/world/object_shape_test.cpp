#include <mrolr/world/ObjectShape.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <filesystem>

using mrolr::world::ObjectShape;
using mrolr::world::ShapePart;
using mrolr::world::WorldError;

TEST(ObjectShape, AllShippedDefinitionsLoad)
{
	int count = 0;
	for (const auto& e :
	     std::filesystem::directory_iterator(std::string(MROLR_SOURCE_DIR) + "/datasets/objects"))
	{
		if (e.path().extension() != ".ini") continue;
		const ObjectShape o = ObjectShape::load(e.path().string());
		EXPECT_EQ(o.name, e.path().stem().string());
		EXPECT_GT(o.heightMm(), 10);
		EXPECT_TRUE(o.has_grasp) << o.name;
		++count;
	}
	EXPECT_GE(count, 6);
}

TEST(ObjectShape, CubeHasLettersOnItsFaces)
{
	const ObjectShape o =
	    ObjectShape::load(std::string(MROLR_SOURCE_DIR) + "/datasets/objects/alphabet_cube.ini");
	ASSERT_EQ(o.parts.size(), 1u);
	EXPECT_EQ(o.parts[0].kind, ShapePart::Kind::Box);
	EXPECT_EQ(o.markings.size(), 5u);
	EXPECT_DOUBLE_EQ(o.heightMm(), 60);
}

TEST(ObjectShape, ErrorsNameSectionAndKey)
{
	auto err = [](const std::string& text)
	{
		return mrolr::test_support::messageOf<WorldError>(
		    [&] { ObjectShape::parse(text, "obj.ini"); }, "no error");
	};
	EXPECT_NE(err("[object]\nname = x\n[part.a]\ntype = sphere\nbase_mm = 0 0 0\n")
	              .find("obj.ini:4 [part.a] type = 'sphere'"),
	          std::string::npos);
	EXPECT_NE(err("[object]\nname = x\n[part.a]\ntype = cylinder\nbase_mm = 0 0 0\nheight_mm = 5\n")
	              .find("radius_bottom_mm: missing key"),
	          std::string::npos);
	EXPECT_NE(err("[object]\nname = x\n[part.a]\ntype = box\nbase_mm = 0 0 0\nsize_mm = 1 1 1\n"
	              "[marking.m]\npart = a\nface = +x\nletter = Q\n")
	              .find("[marking.m] letter = 'Q'"),
	          std::string::npos);
	EXPECT_NE(err("[object]\nname = x\n").find("at least one [part.NAME]"), std::string::npos);
}
