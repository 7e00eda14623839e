// The GUI's console-style command line (docs/gui.md, "Command line"): a line such as
// "1 thru 12 - 4 @ 50" or "group 2 palette Centre" parsed against a show into a selection and
// what to do with it, with errors that name the word where something else was expected, and the
// words that may come next (tab completion). Running a parsed line is in command_run.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

struct ParsedCommand {
  enum class Action {
    None,    // a selection alone (or an empty line)
    Set,     // selection (or the current one) with levels, attributes and palettes
    Record,  // record cue N
    Update,  // update cue N
    GotoCue, // cue N
    Go,
    Clear,
    RecordPalette,  // record [KIND] palette NAME
    UpdatePalette,  // update palette NAME
    DeletePalette,  // delete palette NAME
    RecordGroup,    // record group NAME
    DeleteGroup,    // delete group NAME
    CueTimes,       // cue N time T [delay D] [follow F|off]
    LabelCue,       // label cue N "TEXT"
    DefaultFade,    // default fade T: the fade of cues recorded from now on
    ChangeType,     // [selection] type "FIXTURE TYPE" [mode "MODE"] (docs/fixtures.md)
  };
  Action action = Action::None;
  // The fixtures the line names, sorted; empty when the line names none (Set then uses the
  // current selection).
  std::optional<std::vector<int>> selection;
  // Set: palettes laid first, in the order given, then the levels and attributes over them.
  std::vector<std::string> palettes;  // palette names as in the show
  CueValues values;
  std::string cueNumber;  // Record, Update, GotoCue
  size_t cueList = 0;     // their cue list: an index into Show::cueLists ("cue 2/5": 1)
  // RecordPalette, RecordGroup: the new name as typed; UpdatePalette, DeletePalette,
  // DeleteGroup: the existing one's name as in the show.
  std::string name;
  std::optional<PaletteKind> paletteKind;  // RecordPalette: the kind typed, if any
  // Set: a colour wheel slot, gobo or prism as typed (its name, any case, or its number on the
  // fixture's wheel from 1; "open" for the open slot), resolved per fixture when the line runs.
  std::optional<std::string> colorSlot, goboSlot, prismSlot;
  // CueTimes: the times typed (unset ones stay as they are); a follow of nullopt is "off".
  // DefaultFade: fadeS. LabelCue: the label is in `name`.
  std::optional<double> fadeS, delayS;
  std::optional<std::optional<double>> followS;
  // ChangeType: the type as typed (a library fixture's name or a profile file) in `name`, and
  // the mode ("" = the type's first).
  std::string mode;
};

// The line split into words: '@' and '+' are words of their own wherever they are written, a '-'
// between two digits too ("12-4"); "..." quotes a name with spaces. An unterminated quote is an error.
struct CommandWord {
  std::string text;
  bool quoted = false;
  int position = 0;  // which word of the line as typed, from 1 (what errors name)
};
Result<std::vector<CommandWord>> splitCommandWords(const std::string& line);

// Parses a whole line. An error's place is "word N" (counted from 1) and its message says what was
// expected there ("expected a number after 'thru'").
Result<ParsedCommand> parseCommand(const std::string& line, const Show& show);

// Tab completion: the words that may follow a partial line. When the line does not end in a
// space its last word is a prefix the candidates start with (case-insensitive); names with spaces
// come quoted. `hint` says what is expected when that is not a word from a list ("a fixture id").
struct Completion {
  std::vector<std::string> words;
  std::string hint;
};
Completion completeCommand(const std::string& partialLine, const Show& show);

// The line with its last (partial) word replaced by `word` and a space after it: what Tab does
// when there is exactly one candidate, or the candidates' common prefix (without the space).
std::string applyCompletion(const std::string& partialLine, const Completion& completion);

}  // namespace haze
