// MVR-xchange without sockets: the packet framing against bytes written out by hand from the
// specification's layout, the decoder on streams cut anywhere, the limits, the JSON messages and
// the station's answers.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "fixtures/core/zip_writer.h"
#include "shows/xchange/messages.h"
#include "shows/xchange/packet.h"
#include "shows/xchange/station.h"

namespace haze::xchange {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The header as the specification lays it out, built byte by byte here (not with encodeHeader).
Bytes handHeader(std::uint32_t magic, std::uint32_t version, std::uint32_t number, std::uint32_t count,
                 std::uint32_t type, std::uint64_t length) {
  Bytes b;
  for (std::uint32_t v : {magic, version, number, count, type})
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<std::uint8_t>(v >> s));
  for (int s = 56; s >= 0; s -= 8) b.push_back(static_cast<std::uint8_t>(length >> s));
  return b;
}

Bytes handPacket(std::uint32_t type, const std::string& payload, std::uint32_t number = 0, std::uint32_t count = 1) {
  Bytes b = handHeader(778682, 1, number, count, type, payload.size());
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

std::string text(const Bytes& b) { return std::string(b.begin(), b.end()); }

TEST(XchangePacket, HeaderIsBigEndianAsTheSpecificationLaysItOut) {
  const std::string json = R"({"Type":"MVR_LEAVE"})";
  EXPECT_EQ(encodeJsonPacket(json), handPacket(0, json));
  const auto h = encodeHeader(PayloadType::File, 0x0102030405060708ull, 2, 3);
  EXPECT_EQ(Bytes(h.begin(), h.end()), handHeader(778682, 1, 2, 3, 1, 0x0102030405060708ull));
  // 778682 = 0x000BE1BA
  EXPECT_EQ(h[0], 0x00);
  EXPECT_EQ(h[1], 0x0B);
  EXPECT_EQ(h[2], 0xE1);
  EXPECT_EQ(h[3], 0xBA);
}

TEST(XchangePacket, DecoderTakesAStreamCutAtEveryByte) {
  Bytes stream = handPacket(0, R"({"a":1})");
  const Bytes second = handPacket(1, "PK\x03\x04zipdata");
  stream.insert(stream.end(), second.begin(), second.end());
  for (std::size_t cut = 1; cut <= stream.size(); ++cut) {
    PacketDecoder d;
    for (std::size_t at = 0; at < stream.size(); at += cut) {
      const std::size_t n = std::min(cut, stream.size() - at);
      ASSERT_TRUE(d.feed(std::span<const std::uint8_t>(stream.data() + at, n))) << "cut " << cut;
    }
    Packet p;
    ASSERT_TRUE(d.next(p)) << "cut " << cut;
    EXPECT_EQ(p.type, PayloadType::Json);
    EXPECT_EQ(text(p.payload), R"({"a":1})");
    ASSERT_TRUE(d.next(p));
    EXPECT_EQ(p.type, PayloadType::File);
    EXPECT_EQ(text(p.payload), "PK\x03\x04zipdata");
    EXPECT_FALSE(d.next(p));
    EXPECT_TRUE(d.finish());
  }
}

TEST(XchangePacket, EmptyPayloadAndSplitMessagesJoin) {
  Bytes stream = handPacket(0, "");
  for (const auto& [n, part] : std::vector<std::pair<std::uint32_t, std::string>>{{0, "{\"x\""}, {1, ":"}, {2, "2}"}}) {
    const Bytes b = handPacket(0, part, n, 3);
    stream.insert(stream.end(), b.begin(), b.end());
  }
  PacketDecoder d;
  ASSERT_TRUE(d.feed(stream));
  Packet p;
  ASSERT_TRUE(d.next(p));
  EXPECT_TRUE(p.payload.empty());
  ASSERT_TRUE(d.next(p));
  EXPECT_EQ(text(p.payload), "{\"x\":2}");
  EXPECT_TRUE(d.finish());
}

// Each refusal is one line naming the byte it came at, and the decoder stays refused.
void expectRefused(const Bytes& stream, const std::string& words) {
  PacketDecoder d;
  Status s = d.feed(stream);
  ASSERT_FALSE(s) << words;
  EXPECT_NE(s.error().str().find(words), std::string::npos) << s.error().str();
  EXPECT_EQ(s.error().str().find('\n'), std::string::npos);
  EXPECT_FALSE(d.feed(handPacket(0, "{}")));
  Packet p;
  EXPECT_FALSE(d.next(p));
}

TEST(XchangePacket, HostileHeadersAreRefused) {
  expectRefused(handHeader(778683, 1, 0, 1, 0, 2), "not an MVR-xchange packet");
  expectRefused(handHeader(778682, 2, 0, 1, 0, 2), "version 2");
  expectRefused(handHeader(778682, 1, 0, 1, 7, 2), "unknown MVR-xchange packet type 7");
  expectRefused(handHeader(778682, 1, 0, 0, 0, 2), "packet 0 of 0");
  expectRefused(handHeader(778682, 1, 3, 2, 0, 2), "packet 3 of 2");
  expectRefused(handHeader(778682, 1, 1, 3, 0, 2), "starts with packet 1");
  Bytes wrongNext = handPacket(0, "{", 0, 2);
  const Bytes b = handPacket(1, "}", 1, 2);  // another type continuing the message
  wrongNext.insert(wrongNext.end(), b.begin(), b.end());
  expectRefused(wrongNext, "does not continue");
}

TEST(XchangePacket, LengthsOverTheLimitsAreRefusedFromTheHeaderAlone) {
  // Only the 28 header bytes are fed: the refusal cannot have waited for (or held) a payload.
  expectRefused(handHeader(778682, 1, 0, 1, 0, (1ull << 20) + 1), "JSON payload of 1048577 bytes is over the limit of 1 MiB");
  expectRefused(handHeader(778682, 1, 0, 1, 1, (256ull << 20) + 1), "over the limit of 256 MiB");
  expectRefused(handHeader(778682, 1, 0, 1, 1, ~0ull), "18446744073709551615 bytes");
  // Split messages count together.
  Limits small;
  small.maxJsonBytes = 10;
  PacketDecoder d(small);
  Bytes two = handPacket(0, "123456", 0, 2);
  const Bytes b = handPacket(0, "123456", 1, 2);
  two.insert(two.end(), b.begin(), b.end());
  Status s = d.feed(two);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("12 bytes is over the limit of 10 bytes"), std::string::npos) << s.error().str();
}

TEST(XchangePacket, TruncatedStreamsSaySo) {
  const Bytes whole = handPacket(1, "0123456789");
  PacketDecoder header;
  ASSERT_TRUE(header.feed(std::span<const std::uint8_t>(whole.data(), 10)));
  Status s = header.finish();
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("10 of 28 header bytes"), std::string::npos) << s.error().str();
  PacketDecoder payload;
  ASSERT_TRUE(payload.feed(std::span<const std::uint8_t>(whole.data(), whole.size() - 3)));
  Packet p;
  EXPECT_FALSE(payload.next(p));
  s = payload.finish();
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("7 of 10 payload bytes"), std::string::npos) << s.error().str();
  PacketDecoder split;
  ASSERT_TRUE(split.feed(handPacket(0, "{", 0, 2)));
  EXPECT_FALSE(split.finish());
}

TEST(XchangeMessages, ReadsTheSpecificationsExamples) {
  // The JOIN example: numbers as strings, the list under "Files".
  Result<Message> join = parseMessage(R"({"Type":"MVR_JOIN","Provider":"MVRApplication","verMajor":"1","verMinor":"6",
      "StationUUID":"4AA291A1-1A62-45FE-AABC-E90E5E2399A8","StationName":"Station A",
      "Files":[{"FileUUID":"a7669ff9-bd61-4486-aea6-c190f8ba6b8c","FileSize":256,"verMajor":1,"verMinor":6}]})");
  ASSERT_TRUE(join) << join.error().str();
  EXPECT_EQ(join->type, MessageType::Join);
  EXPECT_EQ(join->provider, "MVRApplication");
  EXPECT_EQ(join->stationUuid, "4aa291a1-1a62-45fe-aabc-e90e5e2399a8");
  EXPECT_EQ(join->verMinor, 6);
  ASSERT_EQ(join->commits.size(), 1u);
  EXPECT_EQ(join->commits[0].fileSize, 256u);
  // OK as the string "true", as in the examples.
  Result<Message> ret = parseMessage(R"({"Type":"MVR_COMMIT_RET","OK":"true","Message":""})");
  ASSERT_TRUE(ret) << ret.error().str();
  EXPECT_TRUE(ret->ok);
  Result<Message> req = parseMessage(R"({"Type":"MVR_REQUEST","FromStationUUID":"","FileUUID":""})");
  ASSERT_TRUE(req) << req.error().str();
  EXPECT_TRUE(req->fileUuid.empty());
  Result<Message> leave = parseMessage(R"({"Type":"MVR_LEAVE","FromStationUUID":"4aa291a1-1a62-45fe-aabc-e90e5e2399a8"})");
  ASSERT_TRUE(leave);
  EXPECT_EQ(leave->fromStationUuid, "4aa291a1-1a62-45fe-aabc-e90e5e2399a8");
}

TEST(XchangeMessages, EveryTypeSurvivesItsOwnJson) {
  Message c;
  c.type = MessageType::Commit;
  c.commit.fileUuid = "a7669ff9-bd61-4486-aea6-c190f8ba6b8c";
  c.commit.stationUuid = "4aa291a1-1a62-45fe-aabc-e90e5e2399a8";
  c.commit.fileSize = 5'000'000'000ull;
  c.commit.comment = "moved the truss";
  c.commit.forStations = {"4aa291a1-1a62-45fe-aabc-e90e5e2399a8"};
  Result<Message> back = parseMessage(toJson(c));
  ASSERT_TRUE(back) << back.error().str();
  EXPECT_EQ(back->commit.fileSize, 5'000'000'000ull);
  EXPECT_EQ(back->commit.comment, "moved the truss");
  EXPECT_EQ(back->commit.forStations, c.commit.forStations);
  // The JSON haze writes carries the field names of the specification's tables.
  const std::string j = toJson(c);
  for (const char* key : {"\"Type\":\"MVR_COMMIT\"", "\"FileUUID\"", "\"FileSize\"", "\"StationUUID\"", "\"verMajor\"",
                          "\"ForStationsUUID\"", "\"Comment\""})
    EXPECT_NE(j.find(key), std::string::npos) << key << " in " << j;
  for (MessageType t : {MessageType::JoinRet, MessageType::LeaveRet, MessageType::CommitRet, MessageType::RequestRet,
                        MessageType::NewSessionHostRet}) {
    Message r = reply(t, false, "no");
    r.stationUuid = c.commit.stationUuid;
    Result<Message> rb = parseMessage(toJson(r));
    ASSERT_TRUE(rb) << messageTypeName(t) << ": " << rb.error().str();
    EXPECT_EQ(rb->type, t);
    EXPECT_FALSE(rb->ok);
    EXPECT_EQ(rb->message, "no");
  }
}

TEST(XchangeMessages, HostileJsonIsRefusedInOneLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[1,2]", "not an object"},
      {"{\"Type\":", "does not parse"},
      {"{}", "no 'Type'"},
      {"{\"Type\":3}", "not a string"},
      {"{\"Type\":\"MVR_SELF_DESTRUCT\"}", "unknown message type 'MVR_SELF_DESTRUCT'"},
      {"{\"Type\":\"MVR_JOIN\",\"StationName\":\"x\",\"StationUUID\":\"4aa291a1-1a62-45fe-aabc-e90e5e2399a8\"}",
       "'Provider' is missing in MVR_JOIN"},
      {"{\"Type\":\"MVR_JOIN\",\"Provider\":\"p\",\"StationName\":\"x\",\"StationUUID\":\"nope\"}", "'StationUUID' in MVR_JOIN is not a uuid"},
      {"{\"Type\":\"MVR_COMMIT\",\"FileUUID\":\"a7669ff9-bd61-4486-aea6-c190f8ba6b8c\"}", "'FileSize' is missing in MVR_COMMIT"},
      {"{\"Type\":\"MVR_COMMIT\",\"FileSize\":-5,\"FileUUID\":\"a7669ff9-bd61-4486-aea6-c190f8ba6b8c\"}", "'FileSize' in MVR_COMMIT is not a whole number"},
      {"{\"Type\":\"MVR_COMMIT_RET\"}", "'OK' is missing in MVR_COMMIT_RET"},
      {"{\"Type\":\"MVR_COMMIT_RET\",\"OK\":\"maybe\"}", "'OK' in MVR_COMMIT_RET is not true or false"},
      {"{\"Type\":\"MVR_LEAVE\"}", "'FromStationUUID' is missing in MVR_LEAVE"},
      {"{\"Type\":\"MVR_JOIN\",\"Provider\":\"p\",\"StationName\":\"x\",\"StationUUID\":\"4aa291a1-1a62-45fe-aabc-e90e5e2399a8\","
       "\"Commits\":[7]}", "Commits[0] of MVR_JOIN is not a JSON object"},
  };
  for (const auto& [json, words] : cases) {
    Result<Message> m = parseMessage(json);
    ASSERT_FALSE(m) << json;
    EXPECT_NE(m.error().str().find(words), std::string::npos) << json << " -> " << m.error().str();
    EXPECT_EQ(m.error().str().find('\n'), std::string::npos);
  }
}

Bytes mvrBytes() {
  Result<Bytes> zip = zipToMemory({{"GeneralSceneDescription.xml",
                                    Bytes{'<', 'G', 'e', 'n', 'e', 'r', 'a', 'l', 'S', 'c', 'e', 'n', 'e', 'D', 'e', 's',
                                          'c', 'r', 'i', 'p', 't', 'i', 'o', 'n', '/', '>'}}},
                                  "test.mvr");
  EXPECT_TRUE(zip);
  return *zip;
}

Packet jsonPacket(const Message& m) {
  const std::string j = toJson(m);
  return Packet{PayloadType::Json, Bytes(j.begin(), j.end())};
}

const char* kHaze = "11111111-2222-4333-8444-555555555555";
const char* kPeer = "4aa291a1-1a62-45fe-aabc-e90e5e2399a8";
const char* kFile = "a7669ff9-bd61-4486-aea6-c190f8ba6b8c";

// A commit of the test file, `size` bytes, as the tests below announce it.
CommitInfo peerFile(std::size_t size) {
  CommitInfo c;
  c.fileUuid = kFile;
  c.fileSize = size;
  return c;
}

TEST(XchangeStation, AnswersJoinWithWhatItOffers) {
  Station haze({"haze test", kHaze});
  const CommitInfo offered = peerFile(123);
  haze.offer(offered);
  Station peer({"peer", kPeer, "Test"});
  Reaction r = haze.receive(7, jsonPacket(peer.join()));
  ASSERT_EQ(r.replies.size(), 1u);
  EXPECT_FALSE(r.close);
  const Message& ret = r.replies[0];
  EXPECT_EQ(ret.type, MessageType::JoinRet);
  EXPECT_TRUE(ret.ok);
  EXPECT_EQ(ret.stationUuid, kHaze);
  ASSERT_EQ(ret.commits.size(), 1u);
  EXPECT_EQ(ret.commits[0].stationUuid, kHaze);
  ASSERT_EQ(haze.joinedPeers(), std::vector<std::string>{kPeer});
  EXPECT_EQ(haze.peers().at(kPeer).name, "peer");
  // The peer reads haze's answer and lists haze with its file.
  Reaction back = peer.receive(1, jsonPacket(ret));
  EXPECT_TRUE(back.replies.empty());
  ASSERT_EQ(peer.peers().count(kHaze), 1u);
  EXPECT_EQ(peer.peers().at(kHaze).commits.at(0).fileUuid, kFile);
  // LEAVE takes the peer out of the commit list.
  r = haze.receive(7, jsonPacket(peer.leave()));
  ASSERT_EQ(r.replies.size(), 1u);
  EXPECT_EQ(r.replies[0].type, MessageType::LeaveRet);
  EXPECT_TRUE(haze.joinedPeers().empty());
}

TEST(XchangeStation, RequestIsAnsweredWithTheFileOrARefusal) {
  Station haze({"haze", kHaze});
  Message req;
  req.type = MessageType::Request;
  Reaction none = haze.receive(1, jsonPacket(req));
  ASSERT_EQ(none.replies.size(), 1u);
  EXPECT_EQ(none.replies[0].type, MessageType::RequestRet);
  EXPECT_FALSE(none.replies[0].ok);
  EXPECT_FALSE(none.sendFile);
  CommitInfo c;
  c.fileUuid = kFile;
  c.fileSize = 99;
  haze.offer(c);
  Reaction latest = haze.receive(1, jsonPacket(req));
  ASSERT_TRUE(latest.sendFile);
  EXPECT_EQ(latest.sendFile->fileUuid, kFile);
  req.fileUuid = kPeer;  // not a file haze has
  Reaction other = haze.receive(1, jsonPacket(req));
  EXPECT_FALSE(other.sendFile);
  ASSERT_EQ(other.replies.size(), 1u);
  EXPECT_FALSE(other.replies[0].ok);
}

TEST(XchangeStation, CommitIsRequestedAndTheFileChecked) {
  const Bytes mvr = mvrBytes();
  Station haze({"haze", kHaze});
  haze.setRequestCommits(true);
  Station peer({"peer", kPeer});
  CommitInfo c = peerFile(mvr.size());
  c.comment = "new rig";
  Reaction r = haze.receive(3, jsonPacket(peer.commit(c)));
  ASSERT_EQ(r.replies.size(), 1u);
  EXPECT_EQ(r.replies[0].type, MessageType::CommitRet);
  ASSERT_TRUE(r.request);
  EXPECT_EQ(r.request->type, MessageType::Request);
  EXPECT_EQ(r.request->fileUuid, kFile);
  EXPECT_EQ(r.request->fromStationUuid, kPeer);
  // The file on another connection was not asked for there.
  Reaction stray = haze.receive(4, Packet{PayloadType::File, mvr});
  EXPECT_TRUE(stray.close);
  EXPECT_FALSE(stray.file);
  Reaction got = haze.receive(3, Packet{PayloadType::File, mvr});
  ASSERT_TRUE(got.file);
  EXPECT_FALSE(got.close);
  EXPECT_EQ(got.file->bytes, mvr);
  EXPECT_EQ(got.file->commit.comment, "new rig");
  // The same commit again is not fetched twice.
  Reaction again = haze.receive(3, jsonPacket(peer.commit(c)));
  EXPECT_FALSE(again.request);
}

TEST(XchangeStation, ABadFileIsRefusedAndNothingHandedOn) {
  const Bytes mvr = mvrBytes();
  Station haze({"haze", kHaze});
  haze.setRequestCommits(true);
  Station peer({"peer", kPeer});
  CommitInfo c = peerFile(mvr.size());
  ASSERT_TRUE(haze.receive(1, jsonPacket(peer.commit(c))).request);
  Bytes notZip(mvr.size(), 'x');
  Reaction r = haze.receive(1, Packet{PayloadType::File, notZip});
  EXPECT_FALSE(r.file);
  EXPECT_TRUE(r.close);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_NE(r.events[0].find("nothing written"), std::string::npos) << r.events[0];
  // A zip without a scene description is not an MVR.
  Result<Bytes> zip = zipToMemory({{"other.txt", Bytes{'h', 'i'}}}, "x");
  ASSERT_TRUE(zip);
  c.fileUuid = "b7669ff9-bd61-4486-aea6-c190f8ba6b8c";
  c.fileSize = zip->size();
  ASSERT_TRUE(haze.receive(2, jsonPacket(peer.commit(c))).request);
  r = haze.receive(2, Packet{PayloadType::File, *zip});
  EXPECT_FALSE(r.file);
  EXPECT_NE(r.events.at(0).find("no GeneralSceneDescription.xml"), std::string::npos) << r.events[0];
  // A size other than the announced one.
  c.fileUuid = "c7669ff9-bd61-4486-aea6-c190f8ba6b8c";
  c.fileSize = mvr.size() + 1;
  ASSERT_TRUE(haze.receive(5, jsonPacket(peer.commit(c))).request);
  r = haze.receive(5, Packet{PayloadType::File, mvr});
  EXPECT_FALSE(r.file);
  EXPECT_NE(r.events.at(0).find("the commit announced"), std::string::npos) << r.events[0];
}

TEST(XchangeStation, CommitsOverTheLimitOrForOthersAreNotRequested) {
  Station haze({"haze", kHaze});
  haze.setRequestCommits(true);
  Station peer({"peer", kPeer});
  CommitInfo big;
  big.fileUuid = kFile;
  big.fileSize = (256ull << 20) + 1;
  Reaction r = haze.receive(1, jsonPacket(peer.commit(big)));
  EXPECT_FALSE(r.request);
  EXPECT_EQ(r.replies.size(), 1u);
  CommitInfo other;
  other.fileUuid = kFile;
  other.fileSize = 10;
  other.forStations = {"99999999-2222-4333-8444-555555555555"};
  EXPECT_FALSE(haze.receive(1, jsonPacket(peer.commit(other))).request);
  // Without requestCommits, a commit is only listed.
  Station quiet({"quiet", kHaze});
  big.fileSize = 10;
  EXPECT_FALSE(quiet.receive(1, jsonPacket(peer.commit(big))).request);
  EXPECT_EQ(quiet.peers().at(kPeer).commits.size(), 1u);
}

TEST(XchangeStation, WhatItKeepsIsBounded) {
  Station haze({"haze", kHaze});
  for (int k = 0; k < 20; ++k) {
    CommitInfo c;
    c.fileUuid = "a7669ff9-bd61-4486-aea6-c190f8ba6b" + std::to_string(10 + k);
    haze.offer(c);
  }
  ASSERT_EQ(haze.offered().size(), Station::kMaxOffered);
  EXPECT_EQ(haze.offered().back().fileUuid, "a7669ff9-bd61-4486-aea6-c190f8ba6b29");
  // A flood of stations and of one station's commits.
  for (int k = 0; k < 300; ++k) {
    char uuid[40];
    std::snprintf(uuid, sizeof uuid, "4aa291a1-1a62-45fe-aabc-%012d", k);
    Station other({"s", uuid});
    (void)haze.receive(1, jsonPacket(other.join()));
  }
  EXPECT_EQ(haze.peers().size(), Station::kMaxPeers);
  Station peer({"peer", kPeer});
  for (int k = 0; k < 40; ++k) {
    CommitInfo c;
    c.fileUuid = kFile;
    c.fileSize = static_cast<std::uint64_t>(k + 1);
    (void)haze.receive(1, jsonPacket(peer.commit(c)));
  }
  // kPeer did not fit among the 256 first stations: its commits were answered, not listed.
  EXPECT_EQ(haze.peers().count(kPeer), 0u);
  Station fresh({"haze", kHaze});
  for (int k = 0; k < 40; ++k) {
    CommitInfo c;
    c.fileUuid = kFile;
    c.fileSize = static_cast<std::uint64_t>(k + 1);
    (void)fresh.receive(1, jsonPacket(peer.commit(c)));
  }
  ASSERT_EQ(fresh.peers().at(kPeer).commits.size(), Station::kMaxPeerCommits);
  EXPECT_EQ(fresh.peers().at(kPeer).commits.back().fileSize, 40u);
}

TEST(XchangeStation, BrokenJsonClosesTheConnection) {
  Station haze({"haze", kHaze});
  const std::string junk = "[\"MVR_JOIN\"]";
  Reaction r = haze.receive(1, Packet{PayloadType::Json, Bytes(junk.begin(), junk.end())});
  EXPECT_TRUE(r.close);
  EXPECT_TRUE(r.replies.empty());
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_NE(r.events[0].find("not an object"), std::string::npos);
  Message host;
  host.type = MessageType::NewSessionHost;
  host.serviceName = "other._mvrxchange._tcp.local.";
  Reaction h = haze.receive(1, jsonPacket(host));
  ASSERT_EQ(h.replies.size(), 1u);
  EXPECT_EQ(h.replies[0].type, MessageType::NewSessionHostRet);
  EXPECT_FALSE(h.replies[0].ok);
}

}  // namespace
}  // namespace haze::xchange
