#include "shows/xchange/mdns.h"

#include <avahi-client/client.h>
#include <avahi-client/lookup.h>
#include <avahi-client/publish.h>
#include <avahi-common/alternative.h>
#include <avahi-common/error.h>
#include <avahi-common/malloc.h>
#include <avahi-common/simple-watch.h>

namespace haze::xchange {

namespace {
constexpr const char* kServiceType = "_mvrxchange._tcp";
constexpr int kMaxFound = 256;  // resolved stations kept waiting for pump()
}  // namespace

bool instanceInGroup(const std::string& instance, const std::string& group) {
  const auto at = instance.rfind('@');
  return at == std::string::npos || instance.substr(at + 1) == group;
}

struct Mdns::State {
  AvahiSimplePoll* poll = nullptr;
  AvahiClient* client = nullptr;
  AvahiEntryGroup* entries = nullptr;
  AvahiServiceBrowser* browser = nullptr;
  Identity me;
  std::string group, instance;
  int port = 0;
  std::vector<Discovered> found;
  std::vector<std::string> notes;

  ~State() {
    if (browser) avahi_service_browser_free(browser);
    if (entries) avahi_entry_group_free(entries);
    if (client) avahi_client_free(client);
    if (poll) avahi_simple_poll_free(poll);
  }

  void publish();
  void browse();
};

namespace {

void onEntries(AvahiEntryGroup* g, AvahiEntryGroupState state, void* data) {
  auto* s = static_cast<Mdns::State*>(data);
  if (state == AVAHI_ENTRY_GROUP_ESTABLISHED) {
    s->notes.push_back("mDNS: announced as \"" + s->instance + "\" (" + kServiceType + ", group " + s->group + ")");
  } else if (state == AVAHI_ENTRY_GROUP_COLLISION) {
    char* other = avahi_alternative_service_name(s->instance.c_str());
    s->notes.push_back("mDNS: the name \"" + s->instance + "\" is taken; announcing as \"" + other + "\"");
    s->instance = other;
    avahi_free(other);
    avahi_entry_group_reset(g);
    s->publish();
  } else if (state == AVAHI_ENTRY_GROUP_FAILURE) {
    s->notes.push_back(std::string("mDNS: announcing failed: ") +
                       avahi_strerror(avahi_client_errno(avahi_entry_group_get_client(g))));
  }
}

void onResolved(AvahiServiceResolver* r, AvahiIfIndex, AvahiProtocol, AvahiResolverEvent event, const char* name,
                const char*, const char*, const char*, const AvahiAddress* address, uint16_t port, AvahiStringList* txt,
                AvahiLookupResultFlags, void* data) {
  auto* s = static_cast<Mdns::State*>(data);
  if (event == AVAHI_RESOLVER_FOUND && address && instanceInGroup(name, s->group) &&
      static_cast<int>(s->found.size()) < kMaxFound) {
    Discovered d;
    char text[AVAHI_ADDRESS_STR_MAX] = {};
    avahi_address_snprint(text, sizeof text, address);
    d.endpoint = Endpoint{text, port};
    d.instance = name;
    for (AvahiStringList* t = txt; t; t = avahi_string_list_get_next(t)) {
      char *key = nullptr, *value = nullptr;
      if (avahi_string_list_get_pair(t, &key, &value, nullptr) != 0) continue;
      if (value && std::string(key) == "StationUUID") d.uuid = normaliseUuid(value);
      if (value && std::string(key) == "StationName") d.name = std::string(value).substr(0, 200);
      avahi_free(key);
      avahi_free(value);
    }
    if (d.uuid != s->me.uuid) s->found.push_back(std::move(d));
  }
  avahi_service_resolver_free(r);
}

void onBrowse(AvahiServiceBrowser*, AvahiIfIndex iface, AvahiProtocol proto, AvahiBrowserEvent event, const char* name,
              const char* type, const char* domain, AvahiLookupResultFlags, void* data) {
  auto* s = static_cast<Mdns::State*>(data);
  if (event == AVAHI_BROWSER_NEW && name && std::string(name) != s->instance)
    avahi_service_resolver_new(s->client, iface, proto, name, type, domain, AVAHI_PROTO_INET, static_cast<AvahiLookupFlags>(0),
                               onResolved, s);
}

void onClient(AvahiClient* c, AvahiClientState state, void* data) {
  auto* s = static_cast<Mdns::State*>(data);
  if (!s->client) s->client = c;  // the first call comes from inside avahi_client_new
  if (state == AVAHI_CLIENT_S_RUNNING && !s->entries) {
    s->publish();
    s->browse();
  } else if (state == AVAHI_CLIENT_FAILURE) {
    s->notes.push_back(std::string("mDNS: the Avahi daemon went away: ") + avahi_strerror(avahi_client_errno(c)));
  }
}

}  // namespace

void Mdns::State::publish() {
  if (!entries) entries = avahi_entry_group_new(client, onEntries, this);
  if (!entries) return;
  const std::string nameTxt = "StationName=" + me.name, uuidTxt = "StationUUID=" + me.uuid;
  const std::string subtype = group + "._sub." + kServiceType;
  int e = avahi_entry_group_add_service(entries, AVAHI_IF_UNSPEC, AVAHI_PROTO_INET, static_cast<AvahiPublishFlags>(0),
                                        instance.c_str(), kServiceType, nullptr, nullptr, static_cast<uint16_t>(port),
                                        nameTxt.c_str(), uuidTxt.c_str(), nullptr);
  if (e == 0)
    e = avahi_entry_group_add_service_subtype(entries, AVAHI_IF_UNSPEC, AVAHI_PROTO_INET, static_cast<AvahiPublishFlags>(0),
                                              instance.c_str(), kServiceType, nullptr, subtype.c_str());
  if (e == 0) e = avahi_entry_group_commit(entries);
  if (e != 0) notes.push_back(std::string("mDNS: announcing failed: ") + avahi_strerror(e));
}

void Mdns::State::browse() {
  browser = avahi_service_browser_new(client, AVAHI_IF_UNSPEC, AVAHI_PROTO_INET, kServiceType, nullptr,
                                      static_cast<AvahiLookupFlags>(0), onBrowse, this);
  if (!browser) notes.push_back(std::string("mDNS: browsing failed: ") + avahi_strerror(avahi_client_errno(client)));
}

Result<std::unique_ptr<Mdns>> Mdns::start(const Identity& me, const std::string& group, int port) {
  std::unique_ptr<Mdns> m(new Mdns());
  m->s_ = std::make_unique<State>();
  State& s = *m->s_;
  s.me = me;
  s.group = group;
  s.instance = (me.name + "@" + group).substr(0, 63);  // a DNS label
  s.port = port;
  s.poll = avahi_simple_poll_new();
  if (!s.poll) return Error{"", "", "mDNS is unavailable: Avahi's event loop could not be made"};
  int error = 0;
  AvahiClient* c = avahi_client_new(avahi_simple_poll_get(s.poll), static_cast<AvahiClientFlags>(0), onClient, &s, &error);
  if (!c) return Error{"", "", std::string("mDNS is unavailable: the Avahi daemon is not reachable (") + avahi_strerror(error) + ")"};
  s.client = c;
  return m;
}

Mdns::~Mdns() = default;

std::vector<Discovered> Mdns::pump() {
  for (int k = 0; k < 64 && avahi_simple_poll_iterate(s_->poll, 0) == 0; ++k) {
  }
  std::vector<Discovered> out;
  out.swap(s_->found);
  return out;
}

std::vector<std::string> Mdns::takeNotes() {
  std::vector<std::string> out;
  out.swap(s_->notes);
  return out;
}

}  // namespace haze::xchange
