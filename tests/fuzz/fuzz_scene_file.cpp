// libFuzzer target: a scene parser on arbitrary text, compiled once per parser: chapter 5's
// sprite scenes (KIT_FUZZ_CLOTH_SCENE undefined) and chapters 6–7's cloth scenes (defined). A
// bad file must end in a UsageError, the chapter's exit 2 naming file, line and key; anything
// else that escapes, a crash, a sanitizer report or a hang is a defect (tests/fuzz/README.md).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <kit/base/usage.hpp>
#include <kit/cloth/cloth_scene_file.hpp>
#include <kit/sprites/sprite_scene_file.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
#ifdef KIT_FUZZ_CLOTH_SCENE
    (void)kit::parse_cloth_scene(text, "fuzz.toml");
#else
    (void)kit::parse_sprite_scene(text, "fuzz.toml");
#endif
  } catch (const kit::UsageError&) {
    // the refusal a bad scene file must get
  }
  return 0;
}
