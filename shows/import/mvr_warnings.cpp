// Folds an MVR import's warnings into kinds (groupMvrWarnings, shows/import/mvr_import.h): a Capture
// export's stub GDTFs give hundreds of warnings that differ only in a channel's name.
#include <cctype>
#include <map>
#include <string>
#include <vector>

#include "shows/import/mvr_import.h"

namespace haze {

namespace {

// The sentence after the place, with digit runs as '#' and quoted text as "..." so that
// "attribute 'Dimmer9'" and "attribute 'Dimmer10'" are one kind. An apostrophe inside a word
// ("fixture's") opens no quote.
std::string kindOf(const std::string& warning) {
  const std::size_t cut = warning.rfind(">: ");
  const std::string message = cut == std::string::npos ? warning : warning.substr(cut + 3);
  std::string key;
  for (std::size_t i = 0; i < message.size(); ++i) {
    const char c = message[i];
    const bool afterLetter = i > 0 && std::isalnum(static_cast<unsigned char>(message[i - 1]));
    if (std::isdigit(static_cast<unsigned char>(c))) {
      while (i + 1 < message.size() && std::isdigit(static_cast<unsigned char>(message[i + 1]))) ++i;
      key += '#';
    } else if ((c == '"' || (c == '\'' && !afterLetter)) && message.find(c, i + 1) != std::string::npos) {
      i = message.find(c, i + 1);
      key += c;
      key += "...";
      key += c;
    } else {
      key += c;
    }
  }
  return key;
}

}  // namespace

std::vector<std::string> groupMvrWarnings(const std::vector<std::string>& warnings) {
  std::vector<std::string> first;     // one per kind, in order
  std::vector<std::size_t> count;
  std::map<std::string, std::size_t> kindIndex;
  for (const std::string& w : warnings) {
    auto [it, fresh] = kindIndex.try_emplace(kindOf(w), first.size());
    if (fresh) {
      first.push_back(w);
      count.push_back(1);
    } else {
      ++count[it->second];
    }
  }
  for (std::size_t i = 0; i < first.size(); ++i)
    if (count[i] > 1) first[i] += " (and " + std::to_string(count[i] - 1) + " more like it)";
  return first;
}

}  // namespace haze
