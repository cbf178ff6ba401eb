// Replay scripts: deterministic runs of the window for tests and measurements. The
// shell plays them (shell.h): one simulated frame of 1/60 s per drawn frame, real
// input ignored.
//
// One event per line, `FRAME WHAT ...`, FRAME counting simulated frames from 0; '#'
// starts a comment. The shell's events, for every mode:
//   10 key W down          a key (GLFW's names: W, UP, LEFT_SHIFT, PAGE_UP, F12, KP_ENTER, ...)
//   80 mouse 120 -30       pointer motion in pixels, as if the cursor were captured
//   81 mouse left down     a button: left, right or middle; down or up
//   82 mousemove 200 150   the pointer to a window position in pixels
//   83 wheel -1            the mouse wheel, in steps (+ away from the user)
//   83 type 1.5            characters typed (no spaces; UTF-8), as a keyboard's char events
//   84 drop a.json         a file dropped on the window (relative to the script)
//   95 resize 800 600      resize the window
//  100 capture out.png     save the frame of this frame (relative to the script)
//  110 mode walk           switch to the named mode
//  120 quit               end the run at once, asking nothing (as a crash would)
//  120 close              the window's close button (a mode may ask first: unsaved changes)
// A mode adds its own events (ReplayVerb): the walk's `viewpoint N`.
// Input (keys, buttons, the pointer, the wheel, drops) reaches the mode at its frame, and
// ImGui through the shell's InputQueue (input_queue.h) with the typed characters, as
// live input does: a key's down and up on one frame reach ImGui in two frames.
#pragma once

#include <any>
#include <filesystem>
#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "base/result.h"
#include "editor/app/input.h"

namespace pw::app {

struct ResizeRequest {
  int width = 0;
  int height = 0;
};
struct CaptureRequest {
  std::filesystem::path path;  // absolute, or as given relative to the working directory
};
struct ModeRequest {
  std::string mode;
};
struct QuitRequest {};   // ends the run at once, asking nothing (as a crash would)
struct CloseRequest {};  // the window's close button: the modes may ask first
struct TypeRequest {     // `type TEXT`: one character event per code point
  std::vector<unsigned> codepoints;
};

// An event of a mode's own kind: `verb` and what the verb's parser made of its words
// (the mode reads it back with std::any_cast to the type its parser returned).
struct ModeEvent {
  std::string verb;
  std::any value;
};

using ReplayAction = std::variant<KeyEvent, MouseButtonEvent, CursorEvent, PointerMotionEvent, ScrollEvent, DropEvent,
                                  ResizeRequest, CaptureRequest, ModeRequest, QuitRequest, ModeEvent, CloseRequest,
                                  TypeRequest>;

struct ReplayEvent {
  int frame = 0;
  ReplayAction what;
};

// The input part of an action (keys, buttons, pointer, wheel, drops), if it is one.
std::optional<InputEvent> inputOf(const ReplayAction& action);

// A mode's own event kind: `FRAME verb WORDS...`. `parse` reads the words after the
// verb (parseReplay checks that nothing is left) and returns the value for ModeEvent,
// or an error saying what was expected, without file:line (parseReplay adds it).
struct ReplayVerb {
  std::string verb;
  std::function<Result<std::any>(std::istream& words)> parse;
};

// Parses a replay script; events come back sorted by frame (stable). Errors give
// file:line and what was expected. Paths (capture, drop) are relative to `baseDir`.
Result<std::vector<ReplayEvent>> parseReplay(const std::string& text, const std::string& nameForErrors,
                                             const std::filesystem::path& baseDir,
                                             const std::vector<ReplayVerb>& modeVerbs = {});
Result<std::vector<ReplayEvent>> readReplay(const std::filesystem::path& path,
                                            const std::vector<ReplayVerb>& modeVerbs = {});

}  // namespace pw::app
