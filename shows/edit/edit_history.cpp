// The undo/redo stacks. Each step keeps a serial number so that "modified since saved" survives
// undo and redo, and trimming the oldest steps keeps memory bounded in long sessions.
#include "shows/edit/edit_history.h"

#include <cassert>

#include "shows/palettes.h"

namespace haze {

StageState withProgrammer(StageState state, const Programmer& programmer, const Show& show) {
  for (const auto& [id, v] : programmer.values) {
    auto it = state.find(id);
    if (it != state.end()) overlayValues(it->second, resolveValues(show, id, v));
  }
  return state;
}

Status EditHistory::run(EditTarget& target, std::unique_ptr<EditCommand> command, bool merge) {
  assert(command && "EditHistory::run: null command");
  Status applied = command->apply(target);
  if (!applied) return applied;
  undone_.clear();
  if (savedSerial_ != 0 && savedSerial_ != topSerial()) {
    // A saved state that was only reachable by redo is gone now.
    bool reachable = false;
    for (const Step& s : done_) reachable = reachable || s.serial == savedSerial_;
    if (!reachable) savedSerial_ = ~std::uint64_t{0};
  }
  // Folding into the saved step would hide the change from modified().
  if (merge && !done_.empty() && done_.back().serial != savedSerial_ && done_.back().command->absorb(*command))
    return Ok{};
  done_.push_back(Step{std::move(command), nextSerial_++});
  if (done_.size() > maxSteps_) {
    done_.erase(done_.begin());
    // The state before the oldest step can no longer be reached by undo.
    if (savedSerial_ == 0) savedSerial_ = ~std::uint64_t{0};
  }
  return Ok{};
}

bool EditHistory::undo(EditTarget& target) {
  if (done_.empty()) return false;
  done_.back().command->undo(target);
  undone_.push_back(std::move(done_.back()));
  done_.pop_back();
  return true;
}

bool EditHistory::redo(EditTarget& target) {
  if (undone_.empty()) return false;
  Status again = undone_.back().command->apply(target);
  // The state is exactly the one the command first applied to, so it cannot fail now.
  assert(again.ok() && "EditHistory::redo: a command failed on the state it succeeded on before");
  (void)again;
  done_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  return true;
}

void EditHistory::clear() {
  done_.clear();
  undone_.clear();
  savedSerial_ = 0;
}

}  // namespace haze
