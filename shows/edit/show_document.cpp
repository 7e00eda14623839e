// ShowDocument (see show_document.h). The cue player keeps references into the show, so it is
// rebuilt after every change and put back on the cue that was active.
#include "shows/edit/show_document.h"

#include <algorithm>
#include <cctype>

#include "shows/playback.h"
#include "shows/show_save.h"

namespace haze {

namespace fs = std::filesystem;

Result<std::unique_ptr<ShowDocument>> ShowDocument::open(const fs::path& file) {
  std::unique_ptr<ShowDocument> d(new ShowDocument());
  auto show = loadShow(file);
  if (!show) return show.error();
  d->show_ = std::move(*show);
  auto profiles = loadProfiles(d->show_);
  if (!profiles) return profiles.error();
  d->profiles_ = std::move(*profiles);
  d->loaded_ = d->profiles_;
  if (!d->show_.venueGltf.empty()) {
    auto venue = loadVenue(d->show_.resolve(d->show_.venueGltf));
    if (!venue) return venue.error();
    d->venue_ = std::move(*venue);
  }
  d->bvh_ = std::make_unique<Bvh>(d->venue_);
  d->resetPlayer();
  return d;
}

Result<std::unique_ptr<ShowDocument>> ShowDocument::blank(const ShowDocument* like) {
  std::unique_ptr<ShowDocument> d(new ShowDocument());
  if (like) {
    // No file yet, so the venue is named by its absolute path until a save makes it relative.
    if (!like->show_.venueGltf.empty())
      d->show_.venueGltf = fs::absolute(like->show_.resolve(like->show_.venueGltf)).lexically_normal().string();
    d->show_.cameras = like->show_.cameras;
    d->show_.atmosphere = like->show_.atmosphere;
    d->venue_ = like->venue_;
  }
  d->bvh_ = std::make_unique<Bvh>(d->venue_);
  d->resetPlayer();
  return d;
}

std::string ShowDocument::title() const {
  return "haze - " + (untitled() ? std::string("untitled") : show_.file.filename().string()) + (modified() ? " *" : "");
}

namespace {

bool sameCues(const std::vector<CueList>& a, const std::vector<CueList>& b) {
  if (a.size() != b.size()) return false;
  for (size_t l = 0; l < a.size(); ++l) {
    if (a[l].name != b[l].name || a[l].cues.size() != b[l].cues.size()) return false;
    for (size_t i = 0; i < a[l].cues.size(); ++i) {
      const Cue &x = a[l].cues[i], &y = b[l].cues[i];
      if (x.number != y.number || x.label != y.label || x.fadeS != y.fadeS || x.delayS != y.delayS ||
          x.followS != y.followS || x.timing != y.timing || x.effects != y.effects || x.values != y.values)
        return false;
    }
  }
  return true;
}

}  // namespace

void ShowDocument::changed() {
  ++revision_;
  // The library follows the show's profile keys (adding a profile is undone and redone there).
  std::erase_if(profiles_, [&](const auto& p) { return !show_.profiles.count(p.first); });
  for (const auto& [key, ref] : show_.profiles)
    if (!profiles_.count(key) && loaded_.count(key)) profiles_[key] = loaded_.at(key);
  // Fixtures that no longer exist leave the selection.
  std::erase_if(selection, [&](int id) { return show_.findFixture(id) == nullptr; });
  // The player holds references into the cue lists and snapshots of their states.
  // Palettes and groups are resolved as cues play, so a changed one changes what the cues show.
  if (!sameCues(show_.cueLists, playerCues_) || show_.palettes != playerPalettes_ || show_.groups != playerGroups_)
    resetPlayer();
}

Status ShowDocument::run(std::unique_ptr<EditCommand> command, bool merge) {
  EditTarget t = target();
  Status s = history_.run(t, std::move(command), merge);
  if (s) changed();
  return s;
}

bool ShowDocument::undo() {
  EditTarget t = target();
  if (!history_.undo(t)) return false;
  changed();
  return true;
}

bool ShowDocument::redo() {
  EditTarget t = target();
  if (!history_.redo(t)) return false;
  changed();
  return true;
}

Result<std::string> ShowDocument::addProfileFile(const fs::path& file) {
  auto profile = loadProfile(file);
  if (!profile) return profile.error();
  // The key: the file name without extension, lower case, made unique.
  std::string stem = file.stem().string();
  if (stem.ends_with(".haze")) stem.resize(stem.size() - 5);
  std::string base;
  for (char c : stem) base += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '-';
  if (base.empty()) base = "profile";
  std::string key = base;
  for (int n = 2; show_.profiles.count(key); ++n) key = base + "-" + std::to_string(n);
  std::error_code ec;
  const fs::path abs = fs::absolute(file, ec).lexically_normal();
  ProfileRef ref;
  ref.path = untitled() ? abs.string()
                        : abs.lexically_relative(fs::absolute(show_.file, ec).parent_path().lexically_normal()).string();
  if (ref.path.empty()) ref.path = abs.string();
  const auto before = loaded_.find(key);
  const std::shared_ptr<const Profile> kept = before == loaded_.end() ? nullptr : before->second;
  loaded_[key] = *profile;
  Status s = run(addProfile(key, ref));
  if (!s) {
    if (kept) loaded_[key] = kept;
    else loaded_.erase(key);
    return s.error();
  }
  return key;
}

Result<ChangeTypeReport> ShowDocument::changeFixtureType(const std::vector<int>& ids, const fs::path& file,
                                                         const std::string& mode) {
  auto profile = loadProfile(file);
  if (!profile) return profile.error();
  std::error_code ec;
  const fs::path abs = fs::absolute(file, ec).lexically_normal();
  const fs::path showDir = untitled() ? fs::path() : fs::absolute(show_.file, ec).parent_path().lexically_normal();
  // The same file already in the show keeps its key.
  std::string key;
  for (const auto& [k, ref] : show_.profiles)
    if (!ref.inlineObject && !ref.path.empty() && (showDir / ref.path).lexically_normal() == abs) key = k;
  ProfileRef ref;
  if (key.empty()) {
    std::string base;
    for (char c : file.stem().string()) base += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '-';
    if (base.empty()) base = "profile";
    key = base;
    for (int n = 2; show_.profiles.count(key); ++n) key = base + "-" + std::to_string(n);
    const fs::path rel = showDir.empty() ? fs::path() : abs.lexically_relative(showDir);
    const bool inside = !rel.empty() && *rel.begin() != "..";
    ref.path = inside ? rel.generic_string() : abs.string();
  }
  const auto before = loaded_.find(key);
  const std::shared_ptr<const Profile> kept = before == loaded_.end() ? nullptr : before->second;
  loaded_[key] = *profile;
  auto report = std::make_shared<ChangeTypeReport>();
  Status s = run(haze::changeFixtureType(ChangeTypeRequest{ids, key, *profile, ref, mode}, report));
  if (!s) {
    if (kept) loaded_[key] = kept;
    else loaded_.erase(key);
    return s.error();
  }
  return *report;
}

Result<int> ShowDocument::placeFixtureAt(const std::string& profileKey, const MountPose& pose) {
  FixturePlacement p;
  p.profile = profileKey;
  p.positionM = pose.positionM;
  p.rotationDeg = pose.rotationDeg;
  const auto prof = profiles_.find(profileKey);
  if (prof != profiles_.end() && prof->second && prof->second->modes.empty()) p.universe.reset();
  const int id = nextFixtureId(show_);
  Status s = run(placeFixture(p));
  if (!s) return s.error();
  selection = {id};
  return id;
}

Result<std::vector<FocusResult>> ShowDocument::focusSelectionOn(const glm::vec3& pointM, const StageState& onStage,
                                                                bool merge) {
  if (selection.empty()) return Error{"", "focus", "select a fixture first, then click the point to aim it at"};
  std::vector<FocusResult> results;
  std::map<int, CueValues> values;
  for (int id : selection) {
    const FixtureDef* f = show_.findFixture(id);
    if (!f) continue;
    const auto prof = profiles_.find(f->profile);
    if (prof == profiles_.end() || !prof->second) continue;
    const auto st = onStage.find(id);
    const Attributes now = st != onStage.end() ? st->second : Attributes{};
    const FocusResult r = focusOnPoint(*f, *prof->second, pointM, now.panDeg, now.tiltDeg);
    results.push_back(r);
    CueValues v;
    v.panDeg = r.panDeg;
    v.tiltDeg = r.tiltDeg;
    values[id] = v;
  }
  Status s = run(setProgrammer(std::move(values)), merge);
  if (!s) return s.error();
  return results;
}

Status ShowDocument::setSelectionValues(const CueValues& values, bool merge) {
  if (selection.empty()) return Error{"", "programmer", "no fixture is selected"};
  std::map<int, CueValues> all;
  for (int id : selection) all[id] = values;
  return run(setProgrammer(std::move(all)), merge);
}

Result<std::string> ShowDocument::recordCue(const std::string& afterNumber, const std::string& label) {
  CueRecord r;
  const CueList* list = cueList();
  r.list = list ? list->name : "";
  r.after = afterNumber;
  if (r.after.empty() && list && !list->cues.empty()) r.after = list->cues.back().number;
  r.label = label;
  const size_t before = list ? list->cues.size() : 0;
  Status s = run(haze::recordCue(std::move(r)));
  if (!s) return s.error();
  // The new cue is the one whose number no cue had before: find it by count and position.
  list = cueList();
  if (!list || list->cues.size() != before + 1) return Error{"", "record", "the cue list did not grow"};
  if (afterNumber.empty()) return list->cues.back().number;
  auto at = findCue(*list, afterNumber);
  return at ? list->cues[*at + 1].number : list->cues.back().number;
}

Result<std::string> ShowDocument::recordCueInList(size_t list, const std::string& label) {
  if (list >= show_.cueLists.size()) return Error{"", "record", "the show has no cue list " + std::to_string(list + 1)};
  CueRecord r;
  r.list = show_.cueLists[list].name;
  if (!show_.cueLists[list].cues.empty()) r.after = show_.cueLists[list].cues.back().number;
  r.label = label;
  const size_t before = show_.cueLists[list].cues.size();
  Status s = run(haze::recordCue(std::move(r)));
  if (!s) return s.error();
  if (show_.cueLists[list].cues.size() != before + 1) return Error{"", "record", "the cue list did not grow"};
  return show_.cueLists[list].cues.back().number;
}

Result<std::string> ShowDocument::recordLook(std::map<int, CueValues> look, const std::string& label) {
  if (look.empty()) return Error{"", "record", "no fixture in the look: nothing to record"};
  CueRecord r;
  const CueList* list = cueList();
  r.list = list ? list->name : "";
  if (list && !list->cues.empty()) r.after = list->cues.back().number;
  r.label = label;
  const size_t before = list ? list->cues.size() : 0;
  Status s = run(haze::recordLook(std::move(r), std::move(look)));
  if (!s) return s.error();
  list = cueList();
  if (!list || list->cues.size() != before + 1) return Error{"", "record", "the cue list did not grow"};
  return list->cues.back().number;
}

Status ShowDocument::save(const fs::path& file, bool force) {
  const fs::path to = file.empty() ? show_.file : file;
  if (to.empty()) return Error{"", "save", "the show has no file yet: use Save as and give a path ending in .haze.json"};
  Status s = saveShow(show_, to, SaveOptions{.force = force});
  if (!s) return s;
  history_.markSaved();
  ++revision_;
  return s;
}

std::set<int> patchConflicts(const Show& show, const ProfileSet& profiles) {
  std::set<int> bad;
  struct Span {
    int id, from, to;
  };
  std::map<int, std::vector<Span>> byUniverse;
  for (const FixtureDef& f : show.fixtures) {
    if (!f.patch) continue;
    const auto fp = modeFootprint(profiles, f.profile, f.mode);
    const Span s{f.id, f.patch->address, f.patch->address + (fp ? *fp : 1) - 1};
    if (s.to > 512 || s.from < 1) bad.insert(f.id);
    for (const Span& o : byUniverse[f.patch->universe])
      if (s.from <= o.to && o.from <= s.to) bad.insert({s.id, o.id});
    byUniverse[f.patch->universe].push_back(s);
  }
  return bad;
}

// --- Playback. ---

void ShowDocument::resetPlayer() {
  // What each list had on stage, by position, and the order the lists last started in.
  std::vector<std::optional<size_t>> cues;
  std::vector<double> masters;
  std::vector<size_t> order;
  if (playbacks_) {
    for (size_t i = 0; i < playbacks_->size(); ++i) {
      cues.push_back(playbacks_->currentCue(i));
      masters.push_back(playbacks_->master(i));
    }
    order = playbacks_->startOrder();
  }
  playbacks_.reset();
  playerCues_ = show_.cueLists;
  playerPalettes_ = show_.palettes;
  playerGroups_ = show_.groups;
  playbacks_ = std::make_unique<Playbacks>(show_, profiles_);
  for (size_t i = 0; i < masters.size() && i < playbacks_->size(); ++i) playbacks_->setMaster(i, masters[i]);
  // Jumps in the old start order give each attribute to the list that had it (the fades are over).
  for (size_t i : order) {
    if (i >= playbacks_->size() || !cues[i]) continue;
    const size_t n = playbacks_->list(i).cues.size();
    if (n > 0) playbacks_->jumpTo(i, std::min(*cues[i], n - 1), lastNowS_);
  }
}

const CueList* ShowDocument::cueList() const { return show_.cueLists.empty() ? nullptr : &show_.cueLists.front(); }

bool ShowDocument::listGo(size_t list, double nowS) { return playbacks_ && playbacks_->go(list, nowS); }
bool ShowDocument::listBack(size_t list, double nowS) { return playbacks_ && playbacks_->back(list, nowS); }
bool ShowDocument::gotoCue(size_t index, double nowS) { return playbacks_ && playbacks_->gotoCue(0, index, nowS); }
bool ShowDocument::listGotoCue(size_t list, size_t index, double nowS) {
  return playbacks_ && playbacks_->gotoCue(list, index, nowS);
}
bool ShowDocument::jumpTo(size_t index, double nowS) { return playbacks_ && playbacks_->jumpTo(0, index, nowS); }

std::optional<size_t> ShowDocument::listCue(size_t list) const {
  if (!playbacks_ || list >= playbacks_->size()) return std::nullopt;
  return playbacks_->currentCue(list);
}

void ShowDocument::setListMaster(size_t list, double level) {
  if (playbacks_) playbacks_->setMaster(list, level);
}

double ShowDocument::listMaster(size_t list) const {
  return playbacks_ && list < playbacks_->size() ? playbacks_->master(list) : 1.0;
}

double ShowDocument::listFadeProgress(size_t list, double nowS) const {
  const auto c = listCue(list);
  const auto startedAt = c ? playbacks_->lastStartS(list) : std::nullopt;
  if (!c || !startedAt || *c >= show_.cueLists[list].cues.size()) return 1.0;
  const Cue& cue = show_.cueLists[list].cues[*c];
  // The whole cue, its last part and the end of its fan included.
  return haze::fadeProgress(CueTiming{cue.delayS, cueDurationS(show_, cue) - cue.delayS}, nowS - *startedAt);
}

bool ShowDocument::fading(double nowS) const {
  if (!playbacks_) return false;
  for (size_t i = 0; i < playbacks_->size(); ++i)
    if (playbacks_->fading(i, nowS)) return true;
  return false;
}

StageState ShowDocument::stageState(double nowS) {
  lastNowS_ = nowS;
  StageState s = playbacks_ ? playbacks_->state(nowS) : defaultState(show_);
  // Fixtures placed or deleted since the player was built: at their defaults, or gone.
  for (const auto& [id, a] : defaultState(show_)) s.try_emplace(id, a);
  std::erase_if(s, [&](const auto& entry) { return show_.findFixture(entry.first) == nullptr; });
  return withProgrammer(std::move(s), programmer_, show_);
}

}  // namespace haze
