// tests/io/scene_heads_test.cpp — a scene listener's "head" and the scene's "audio.hrtf"
// (docs/scene.md; docs/binaural.md): read into the records, `up` defaulting to against gravity,
// and each bad setting named by its JSON path before any work.
#include <gtest/gtest.h>

#include "io/bubble_histories.h"
#include "io/hrir_file.h"
#include "io/scene_file.h"
#include "io/scene_documents.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

using namespace scene_test;

json withHeadListener(const char* head) {
  return withChange(minimalScene(), "/listeners",
                    (std::string(R"([{"name": "a", "position": [0, 0.5, 0]}, {"name": "b", "position": [0, 0.5, 1], "head": )") +
                     head + "}]").c_str());
}

TEST(SceneHeads, AHeadIsReadAndItsUpDefaultsToAgainstGravity) {
  const sim::Scene scene = parseScene(withHeadListener(R"({"facing": [0, 0, -1]})").dump(), "tank.json");
  ASSERT_EQ(scene.listeners.size(), 2u);
  EXPECT_FALSE(scene.listeners[0].head);
  ASSERT_TRUE(scene.listeners[1].head);
  EXPECT_EQ(scene.listeners[1].head->facing, (Vec3{0.0, 0.0, -1.0}));
  EXPECT_EQ(scene.listeners[1].head->up, (Vec3{0.0, 9.81, 0.0}));  // gravity −9.81 y
  const sim::Scene turned =
      parseScene(withHeadListener(R"({"facing": [1, 0, 0], "up": [0, 0, 1]})").dump(), "tank.json");
  EXPECT_EQ(turned.listeners[1].head->up, (Vec3{0.0, 0.0, 1.0}));
  // The bubble file carries the head to the synth stage.
  const acoustics::BubbleTrackSet tracks = bubbleTracksFromHistories({}, turned);
  ASSERT_EQ(tracks.heads.size(), 1u);
  EXPECT_EQ(tracks.heads[0].listener, "b");
  EXPECT_EQ(tracks.heads[0].position, (Vec3{0.0, 0.5, 1.0}));
  EXPECT_FALSE(tracks.hrtf);  // the default set
}

TEST(SceneHeads, EachBadHeadSettingIsNamed) {
  expectError(parseError(withHeadListener(R"({"facing": [0, 0, 0]})").dump()), "listeners[1].head.facing",
              "a non-zero direction");
  expectError(parseError(withHeadListener(R"({"facing": [0, 2, 0]})").dump()), "listeners[1].head.facing",
              "a direction not parallel to up, which defaults to against gravity");
  expectError(parseError(withHeadListener(R"({"facing": [1, 0, 0], "up": [-3, 0, 0]})").dump()),
              "listeners[1].head.up", "a non-zero direction not parallel to facing");
  expectError(parseError(withHeadListener(R"({"up": [0, 1, 0]})").dump()), "listeners[1].head.facing",
              "an array of 3 numbers [x, y, z] (direction the nose points), found nothing");
  expectError(parseError(withHeadListener(R"({"facing": [1, 0, 0], "nose": 1})").dump()), "listeners[1].head.nose",
              "one of");
  expectError(parseError(withHeadListener(R"("ahead")").dump()), "listeners[1].head", "an object with facing and up");
}

TEST(SceneHeads, AnHrtfFileThatIsNotASofaSetIsNamedAtAudioHrtf) {
  test::TempFolder folder;
  writeFile(folder.path() / "set.sofa", "not a SOFA file");
  const json document = withChange(withHeadListener(R"({"facing": [1, 0, 0]})"), "/audio", R"({"hrtf": "set.sofa"})");
  const InputError error = test::inputErrorOf(
      [&](const std::string& t) { parseScene(t, folder.path() / "tank.json"); }, document.dump());
  EXPECT_EQ(error.field(), "audio.hrtf");
  EXPECT_NE(std::string(error.what()).find("set.sofa"), std::string::npos) << error.what();
  const InputError missing = test::inputErrorOf(
      [&](const std::string& t) { parseScene(t, folder.path() / "tank.json"); },
      withChange(document, "/audio/hrtf", R"("nowhere.sofa")").dump());
  EXPECT_EQ(missing.field(), "audio.hrtf");
  EXPECT_NE(std::string(missing.what()).find("no such file"), std::string::npos) << missing.what();
  // The set Debian ships is accepted, by any path.
  const std::string quoted = nlohmann::json(defaultHrirFile().string()).dump();  // a JSON string
  const sim::Scene scene =
      parseScene(withChange(document, "/audio/hrtf", quoted.c_str()).dump(), folder.path() / "tank.json");
  EXPECT_EQ(scene.hrtf, defaultHrirFile());
}

}  // namespace
}  // namespace fluidsound::io
