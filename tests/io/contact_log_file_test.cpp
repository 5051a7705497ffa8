// tests/io/contact_log_file_test.cpp — contacts.bin (`fluidsound.contacts/1`,
// io/contact_log_file.h): the same bits back, little-endian on every host, every check of the
// reader naming its field, every cut of a file refused, a crafted record count refused before any
// allocation, and a path that is not a regular file left alone. The committed fuzz seeds
// (tests/fuzz/corpus/contact_log/) are what the encoder writes: FLUIDSOUND_WRITE_CONTACT_SEEDS=1
// rewrites them.
#include "io/contact_log_file.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "io/input_error.h"
#include "sim/core/contact_record.h"
#include "sim/core/quaternion.h"
#include "support/file_bytes.h"
#include "support/input_error_expectations.h"
#include "support/special_files.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

const std::string kFile = "contacts.bin";
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Where the first body starts: the magic, the body count, substep and duration.
constexpr std::size_t kBodiesStart = 22 + 4 + 8 + 8;

sim::ContactRecord contact(double time, int bodyA, int bodyB, const Vec3& normal) {
  sim::ContactRecord r;
  r.time = time;
  r.bodyA = bodyA;
  r.bodyB = bodyB;
  r.position = {0.01, 0.02, 0.005};
  r.normal = normal;
  r.normalImpulse = 0.0125;
  r.frictionImpulse = {1e-4, -2e-5, 0.0};
  r.normalSpeed = 1.98;
  r.tangentialSpeed = 0.03;
  r.rollingRate = 0.5;
  r.lifetime = 1;
  r.localPointA = {0.0, 0.0, 0.01};
  r.localPointB = {0.01, 0.02, 0.0};
  return r;
}

/// The empty log of a run without bodies.
sim::ContactLog emptyLog() {
  sim::ContactLog log;
  log.substep = 1e-3;
  log.duration = 0.0;
  return log;
}

/// One ball that touches the floor (the wall on face 4, −z: bodyB = −5) in two substeps.
sim::ContactLog ballOnFloor() {
  sim::ContactLog log;
  log.substep = 1e-3;
  log.duration = 0.25;
  log.bodies = {{"ball", 0.0041, false, 0.005}};
  log.records = {contact(0.202, 0, -5, {0, 0, 1}), contact(0.203, 0, -5, {0, 0, 1})};
  log.records[1].lifetime = 2;
  log.records[1].normalSpeed = -0.4;  // separating: the closing speed is signed
  return log;
}

/// A static table (body 0) and a ball on it that also touches a wall, in one substep.
sim::ContactLog ballOnTable() {
  sim::ContactLog log;
  log.substep = 5e-4;
  log.duration = 0.5;
  log.bodies = {{"table", 0.0, true, 0.25}, {"ball", 0.0041, false, 0.005}};
  log.records = {contact(0.2025, 0, 1, {0, 0, -1}), contact(0.2025, 1, -2, {-1, 0, 0})};
  log.records[0].orientationB = sim::quaternionFromAxisAngle({0, 1, 0}, 0.3);
  log.records[1].orientationA = log.records[0].orientationB;
  return log;
}

/// Three bodies, a wall record, rotated bodies, awkward bits: −0, a subnormal, 0.1, 1/3.
sim::ContactLog richLog() {
  sim::ContactLog log;
  log.substep = 1.0 / 3.0 * 1e-3;
  log.duration = 1.0 / 3.0;
  log.bodies = {{"table", 0.0, true, 0.25},
                {"kugel \xc3\xa4 \xe2\x9c\x93", 0.1, false, 0.005},
                {"box", 1.0 / 7.0, false, 0.02}};
  const sim::Quaternion turned = sim::quaternionFromAxisAngle({1, 2, 3}, 0.7);
  log.records = {contact(0.1, 0, 1, {0, 0, -1}),
                 contact(0.1, 0, 2, {1.0 / 3.0, 2.0 / 3.0, -2.0 / 3.0}),
                 contact(0.1, 1, -6, {0, 0, -1}), contact(1.0 / 3.0 + 1e-4, 2, -1, {1, 0, 0})};
  log.records[0].frictionImpulse = {-0.0, std::numeric_limits<double>::denorm_min(), 0.1};
  log.records[1].orientationB = turned;
  log.records[2].orientationA = turned * turned;
  log.records[2].lifetime = 123456;
  log.records[3].normalSpeed = -1e-300;
  log.records[3].localPointA = {-0.0, 1e300, -1e-300};
  return log;
}

std::vector<std::uint64_t> doubleBits(const sim::ContactLog& log) {
  std::vector<std::uint64_t> bits;
  const auto add = [&](double v) { bits.push_back(std::bit_cast<std::uint64_t>(v)); };
  add(log.substep);
  add(log.duration);
  for (const auto& b : log.bodies) add(b.mass), add(b.contactRadius);
  for (const auto& r : log.records) {
    for (double v : {r.time, r.normalImpulse, r.normalSpeed, r.tangentialSpeed, r.rollingRate})
      add(v);
    for (const Vec3* v :
         {&r.position, &r.normal, &r.frictionImpulse, &r.localPointA, &r.localPointB})
      for (double c : *v) add(c);
    for (const sim::Quaternion* q : {&r.orientationA, &r.orientationB})
      for (double c : {q->w, q->x, q->y, q->z}) add(c);
  }
  return bits;
}

void putLittleEndian(std::string& bytes, std::size_t offset, std::uint64_t value, int size) {
  for (int i = 0; i < size; ++i) bytes[offset + i] = static_cast<char>((value >> (8 * i)) & 0xff);
}

std::uint64_t readLittleEndian(const std::string& bytes, std::size_t offset, int size) {
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i)
    value |= std::uint64_t{static_cast<unsigned char>(bytes[offset + i])} << (8 * i);
  return value;
}

/// Where the u64 record count of `bytes` (holding `records` records) is.
std::size_t recordCountOffset(const std::string& bytes, std::size_t records) {
  return bytes.size() - records * kContactRecordBytes - 8;
}

/// The InputError decoding `bytes` throws (a test failure if none, or if anything else is thrown).
InputError errorOf(const std::string& bytes) {
  try {
    decodeContactLog(bytes, kFile);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for " << bytes.size() << " bytes";
  return InputError("", "", "");
}

TEST(ContactLogFile, RoundTripKeepsEveryBit) {
  for (const sim::ContactLog& log : {emptyLog(), ballOnFloor(), ballOnTable(), richLog()}) {
    const std::string bytes = encodeContactLog(log);
    const sim::ContactLog back = decodeContactLog(bytes, kFile);
    EXPECT_EQ(back, log);
    EXPECT_EQ(doubleBits(back), doubleBits(log));  // == cannot tell −0 from 0
    EXPECT_EQ(encodeContactLog(back), bytes);
  }
  const sim::ContactLog back = decodeContactLog(encodeContactLog(richLog()), kFile);
  EXPECT_TRUE(std::signbit(back.records[0].frictionImpulse[0]));
  EXPECT_EQ(back.records[2].bodyB, -6);
  EXPECT_EQ(back.records[1].orientationB, sim::quaternionFromAxisAngle({1, 2, 3}, 0.7));
  EXPECT_EQ(back.bodies[1].name, "kugel \xc3\xa4 \xe2\x9c\x93");
}

TEST(ContactLogFile, BytesAreLittleEndianInTheDocumentedLayout) {
  // The empty log, byte by byte: magic, u32 0 bodies, f64 1e-3 (0x3f50624dd2f1a9fc), f64 0, u64 0.
  const std::string empty = encodeContactLog(emptyLog());
  const std::string expected = std::string("fluidsound.contacts/1\n") + std::string(4, '\0') +
                               "\xfc\xa9\xf1\xd2\x4d\x62\x50\x3f" + std::string(16, '\0');
  EXPECT_EQ(empty, expected);

  sim::ContactLog log = ballOnTable();
  sim::ContactRecord& r = log.records[1];
  r.lifetime = 0x01020304;
  r.orientationB = {0.0, 0.0, 0.0, 1.0};
  const std::string bytes = encodeContactLog(log);
  // Bodies: 4 + 5 + 8 + 1 + 8 ("table") and 4 + 4 + 8 + 1 + 8 ("ball"), then the count.
  ASSERT_EQ(bytes.size(), kBodiesStart + 26 + 25 + 8 + 2 * kContactRecordBytes);
  EXPECT_EQ(readLittleEndian(bytes, 22, 4), 2u);
  EXPECT_EQ(readLittleEndian(bytes, kBodiesStart, 4), 5u);
  EXPECT_EQ(bytes.substr(kBodiesStart + 4, 5), "table");
  EXPECT_EQ(readLittleEndian(bytes, kBodiesStart + 17, 1), 1u);  // isStatic
  EXPECT_EQ(readLittleEndian(bytes, recordCountOffset(bytes, 2), 8), 2u);
  const std::size_t second = bytes.size() - kContactRecordBytes;
  EXPECT_EQ(readLittleEndian(bytes, second, 8), std::bit_cast<std::uint64_t>(0.2025));  // time
  EXPECT_EQ(readLittleEndian(bytes, second + 8, 4), 1u);                                // bodyA
  EXPECT_EQ(readLittleEndian(bytes, second + 12, 4), 0xfffffffeu);  // bodyB −2
  EXPECT_EQ(readLittleEndian(bytes, second + 40, 8),
            std::bit_cast<std::uint64_t>(-1.0));                     // normal x
  EXPECT_EQ(readLittleEndian(bytes, second + 120, 4), 0x01020304u);  // lifetime
  EXPECT_EQ(readLittleEndian(bytes, second + 228, 8),
            std::bit_cast<std::uint64_t>(1.0));  // orientationB.z
}

TEST(ContactLogFile, FileRoundTripAndReadErrors) {
  test::TempFolder folder;
  const auto file = folder.path() / "contacts.bin";
  writeContactLog(file, richLog());
  EXPECT_EQ(test::fileBytes(file), encodeContactLog(richLog()));
  EXPECT_EQ(readContactLog(file), richLog());
  writeContactLog(file, ballOnFloor());  // a regular file is replaced
  EXPECT_EQ(readContactLog(file), ballOnFloor());
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"contacts.bin"});

  for (const auto& bad : {folder.path() / "missing.bin", folder.path()}) {
    try {
      readContactLog(bad);
      ADD_FAILURE() << "read " << bad;
    } catch (const InputError& error) {
      test::expectInputError(error, bad.string(), "", "a readable file",
                             test::ExpectedAt::RightAfterHead);
    }
  }
  std::ofstream(file, std::ios::binary | std::ios::trunc) << "fluidsound.contacts/2\n";
  try {
    readContactLog(file);
    ADD_FAILURE() << "read a wrong version";
  } catch (const InputError& error) {
    test::expectInputError(error, file.string(), "format", "the bytes \"fluidsound.contacts/1\\n\"",
                           test::ExpectedAt::RightAfterHead);
  }
}

struct LogCase {
  const char* what;
  std::function<void(sim::ContactLog&)> change;
  std::string field;
  std::string expected;
};

TEST(ContactLogFile, EveryCheckNamesItsField) {
  using L = sim::ContactLog;
  const std::vector<LogCase> cases = {
      {"substep 0", [](L& l) { l.substep = 0; }, "substep",
       "a finite number > 0 and <= 0.001 (seconds)"},
      {"substep 2 ms", [](L& l) { l.substep = 2e-3; }, "substep", "> 0 and <= 0.001"},
      {"substep NaN", [](L& l) { l.substep = kNan; }, "substep", "a finite number"},
      {"duration < 0", [](L& l) { l.duration = -1; }, "duration", "a finite number >= 0 (seconds)"},
      {"duration inf", [](L& l) { l.duration = kInf; }, "duration", "a finite number >= 0"},
      {"name of 1025 bytes", [](L& l) { l.bodies[1].name = std::string(1025, 'a'); },
       "bodies[1].name", "a name of at most 1024 bytes"},
      {"name not UTF-8", [](L& l) { l.bodies[1].name = "ball\xff"; }, "bodies[1].name",
       "a name in UTF-8"},
      {"name with a surrogate", [](L& l) { l.bodies[0].name = "\xed\xa0\x80"; }, "bodies[0].name",
       "a name in UTF-8"},
      {"name overlong", [](L& l) { l.bodies[0].name = "\xc0\xaf"; }, "bodies[0].name",
       "a name in UTF-8"},
      {"name cut in a character", [](L& l) { l.bodies[0].name = "t\xe2\x9c"; }, "bodies[0].name",
       "a name in UTF-8"},
      {"mass < 0", [](L& l) { l.bodies[1].mass = -1; }, "bodies[1].mass",
       "a finite number >= 0 (kg)"},
      {"mass NaN", [](L& l) { l.bodies[1].mass = kNan; }, "bodies[1].mass",
       "a finite number >= 0 (kg)"},
      {"static with mass", [](L& l) { l.bodies[0].mass = 2; }, "bodies[0].mass",
       "0 for a static body"},
      {"moving without mass", [](L& l) { l.bodies[1].mass = 0; }, "bodies[1].mass",
       "a number > 0 for a body that is not static"},
      {"contact radius 0", [](L& l) { l.bodies[1].contactRadius = 0; }, "bodies[1].contactRadius",
       "a finite number > 0 (metres)"},
      {"contact radius inf", [](L& l) { l.bodies[0].contactRadius = kInf; },
       "bodies[0].contactRadius", "a finite number > 0"},
      {"time NaN", [](L& l) { l.records[0].time = kNan; }, "records[0].time",
       "a number from 0 to duration + substep"},
      {"time < 0", [](L& l) { l.records[0].time = -1e-3; }, "records[0].time",
       "a number from 0 to"},
      {"time after the end", [](L& l) { l.records[2].time = 0.5 + 5e-4 + 1e-9; }, "records[2].time",
       "duration + substep = 0.5005"},
      {"time decreasing", [](L& l) { l.records[2].time = 0.2; }, "records[2].time",
       "a time >= 0.2025 (seconds), that of records[1]"},
      {"no bodies", [](L& l) { l.bodies.clear(); }, "records[0].bodyA",
       "no record (the log has no bodies)"},
      {"bodyA < 0", [](L& l) { l.records[0].bodyA = -1; }, "records[0].bodyA",
       "a body index from 0 to 1"},
      {"bodyA = bodies", [](L& l) { l.records[2].bodyA = 2; }, "records[2].bodyA",
       "a body index from 0 to 1"},
      {"bodyB = bodyA", [](L& l) { l.records[0].bodyB = 0; }, "records[0].bodyB",
       "a body after bodyA (1 to 1) or a wall of the domain (-6 to -1)"},
      {"bodyB = bodies", [](L& l) { l.records[0].bodyB = 2; }, "records[0].bodyB",
       "a body after bodyA"},
      {"bodyB < bodyA", [](L& l) { l.records[2].bodyB = 0; }, "records[2].bodyB",
       "a wall of the domain (-6 to -1), bodyA 1 being the last body"},
      {"bodyB no wall", [](L& l) { l.records[1].bodyB = -7; }, "records[1].bodyB",
       "a wall of the domain (-6 to -1)"},
      {"pairs out of order (bodyA)", [](L& l) { std::swap(l.records[0], l.records[1]); },
       "records[1].bodyA",
       "a pair (bodyA, bodyB) not before (1, -2) of records[0], at the same time"},
      {"pairs out of order (bodyB)", [](L& l) { l.records[1].bodyA = 0, l.records[1].bodyB = -1; },
       "records[1].bodyB", "not before (0, 1) of records[0]"},
      {"position inf", [](L& l) { l.records[1].position[2] = kInf; }, "records[1].position",
       "3 finite numbers (metres)"},
      {"normal too long",
       [](L& l) {
         l.records[1].normal = {0, 0, 1 + 2e-6};
       },
       "records[1].normal", "a unit vector (length within 1e-06 of 1)"},
      {"normal zero",
       [](L& l) {
         l.records[0].normal = {0, 0, 0};
       },
       "records[0].normal", "a unit vector"},
      {"normal NaN", [](L& l) { l.records[0].normal[0] = kNan; }, "records[0].normal",
       "a unit vector"},
      {"normal impulse < 0", [](L& l) { l.records[0].normalImpulse = -1e-12; },
       "records[0].normalImpulse", "a finite number >= 0 (newton seconds)"},
      {"friction NaN", [](L& l) { l.records[0].frictionImpulse[1] = kNan; },
       "records[0].frictionImpulse", "3 finite numbers"},
      {"normal speed inf", [](L& l) { l.records[0].normalSpeed = -kInf; }, "records[0].normalSpeed",
       "a finite number (m/s)"},
      {"tangential speed < 0", [](L& l) { l.records[0].tangentialSpeed = -1e-9; },
       "records[0].tangentialSpeed", "a finite number >= 0 (m/s)"},
      {"rolling rate < 0", [](L& l) { l.records[1].rollingRate = -1; }, "records[1].rollingRate",
       "a finite number >= 0 (rad/s)"},
      {"lifetime 0", [](L& l) { l.records[1].lifetime = 0; }, "records[1].lifetime",
       "an integer >= 1 (substeps)"},
      {"local point A NaN", [](L& l) { l.records[0].localPointA[0] = kNan; },
       "records[0].localPointA", "3 finite numbers"},
      {"local point B inf", [](L& l) { l.records[0].localPointB[2] = kInf; },
       "records[0].localPointB", "3 finite numbers"},
      {"orientation A not unit",
       [](L& l) {
         l.records[0].orientationA = {1, 1, 0, 0};
       },
       "records[0].orientationA", "a unit quaternion (w, x, y, z; length within 1e-06 of 1)"},
      {"orientation B NaN", [](L& l) { l.records[1].orientationB.z = kNan; },
       "records[1].orientationB", "a unit quaternion"},
  };
  for (const LogCase& c : cases) {
    SCOPED_TRACE(c.what);
    sim::ContactLog log = ballOnTable();
    log.records.push_back(contact(0.2035, 1, -5, {0, 0, 1}));
    ASSERT_NO_THROW(decodeContactLog(encodeContactLog(log), kFile));
    c.change(log);
    test::expectInputError(errorOf(encodeContactLog(log)), kFile, c.field, c.expected,
                           test::ExpectedAt::Anywhere);
  }
}

struct ByteCase {
  const char* what;
  std::function<void(std::string&)> change;
  std::string field;
  std::string expected;
};

TEST(ContactLogFile, DamagedBytesNameTheirPart) {
  const std::string good = encodeContactLog(ballOnTable());
  const std::size_t count = recordCountOffset(good, 2);
  const std::vector<ByteCase> cases = {
      {"empty file", [](std::string& b) { b.clear(); }, "format",
       "the bytes \"fluidsound.contacts/1\\n\""},
      {"another format", [](std::string& b) { b[11] = 'm'; }, "format",
       "(a fluidsound contact log)"},
      {"a text file", [](std::string& b) { b = "{\"format\": \"fluidsound.bubbles/1\"}"; },
       "format", "the bytes"},
      {"4097 bodies", [](std::string& b) { putLittleEndian(b, 22, 4097, 4); }, "bodies",
       "at most 4096 bodies"},
      {"isStatic 2", [](std::string& b) { b[kBodiesStart + 17] = 2; }, "bodies[0].isStatic",
       "0 or 1"},
      {"name length 2^32 - 1",
       [](std::string& b) { putLittleEndian(b, kBodiesStart, 0xffffffff, 4); }, "bodies[0].name",
       "a name of at most 1024 bytes"},
      {"trailing byte", [](std::string& b) { b += '\0'; }, "records",
       "the end of the file after 2 records of 236 bytes"},
      {"trailing record", [&](std::string& b) { b += b.substr(b.size() - kContactRecordBytes); },
       "records", "the end of the file after 2 records"},
      {"one record fewer", [&](std::string& b) { putLittleEndian(b, count, 1, 8); }, "records",
       "the end of the file after 1 record of"},
      {"cut in the substep", [](std::string& b) { b.resize(30); }, "substep",
       "a float64 (8 bytes)"},
      {"cut in a name", [](std::string& b) { b.resize(kBodiesStart + 6); }, "bodies[0].name",
       "the name's 5 bytes"},
      {"cut in the record count", [&](std::string& b) { b.resize(count + 3); }, "records",
       "a uint64 record count (8 bytes)"},
      {"cut in a record", [](std::string& b) { b.pop_back(); }, "records[1]",
       "a whole record of 236 bytes (the record count is 2)"},
  };
  for (const ByteCase& c : cases) {
    SCOPED_TRACE(c.what);
    std::string bytes = good;
    c.change(bytes);
    test::expectInputError(errorOf(bytes), kFile, c.field, c.expected, test::ExpectedAt::Anywhere);
  }
}

TEST(ContactLogFile, EveryCutOfAFileIsRefused) {
  for (const sim::ContactLog& log : {emptyLog(), ballOnFloor(), ballOnTable()}) {
    const std::string bytes = encodeContactLog(log);
    for (std::size_t size = 0; size < bytes.size(); ++size) {
      const InputError error = errorOf(bytes.substr(0, size));
      EXPECT_FALSE(error.field().empty()) << size << ": " << error.what();
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << size;
    }
  }
}

TEST(ContactLogFile, CraftedRecordCountIsRefusedBeforeAllocating) {
  // Each count would need far more than any machine's memory (2^40 records: 260 TB): were it
  // allocated before the check, the error would be std::bad_alloc or std::length_error instead.
  const std::string good = encodeContactLog(ballOnTable());
  for (const std::uint64_t crafted :
       {std::uint64_t{3}, std::uint64_t{1} << 40, std::uint64_t{1} << 62,
        std::numeric_limits<std::uint64_t>::max()}) {
    SCOPED_TRACE(crafted);
    std::string bytes = good;
    putLittleEndian(bytes, recordCountOffset(good, 2), crafted, 8);
    test::expectInputError(
        errorOf(bytes), kFile, "records[2]",
        "a whole record of 236 bytes (the record count is " + std::to_string(crafted) + ")",
        test::ExpectedAt::RightAfterHead);
  }
  // Counts and lengths before the records are bounded too: 4096 bodies whose bytes are missing.
  std::string bodies = encodeContactLog(emptyLog());
  putLittleEndian(bodies, 22, 4096, 4);
  bodies.resize(kBodiesStart);
  test::expectInputError(errorOf(bodies), kFile, "bodies[0].name", "a uint32 name length",
                         test::ExpectedAt::Anywhere);
}

TEST(ContactLogFile, WriteRefusesWhatIsNotARegularFileAndLeavesItAlone) {
  test::TempFolder folder;
  const auto fifo = folder.path() / "fifo.bin";
  ASSERT_TRUE(test::makeFifo(fifo));
  EXPECT_THROW(writeContactLog(fifo, ballOnFloor()), OutputError);
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));

  const auto directory = folder.path() / "contacts.bin";
  std::filesystem::create_directory(directory);
  std::ofstream(directory / "inside.txt") << "kept";
  EXPECT_THROW(writeContactLog(directory, ballOnFloor()), OutputError);
  EXPECT_TRUE(std::filesystem::is_directory(directory));
  EXPECT_EQ(test::fileBytes(directory / "inside.txt"), "kept");
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{"contacts.bin", "fifo.bin"}));  // no temporary left
}

TEST(ContactLogFile, WriteRefusesAnInvalidLogAndWritesNothing) {
  test::TempFolder folder;
  const auto file = folder.path() / "contacts.bin";
  writeContactLog(file, ballOnFloor());
  sim::ContactLog bad = ballOnTable();
  bad.records[0].normal = {0, 0, 2};
  try {
    writeContactLog(file, bad);
    ADD_FAILURE() << "wrote an invalid log";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("records[0].normal: expected a unit vector"),
              std::string::npos)
        << error.what();
  }
  EXPECT_EQ(readContactLog(file), ballOnFloor());
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"contacts.bin"});
}

TEST(ContactLogFile, SeedCorpusIsWhatTheEncoderWrites) {
  const std::filesystem::path corpus =
      std::filesystem::path(FLUIDSOUND_SOURCE_DIR) / "tests/fuzz/corpus/contact_log";
  const std::vector<std::pair<std::string, sim::ContactLog>> seeds = {
      {"empty.bin", emptyLog()},
      {"ball_on_floor.bin", ballOnFloor()},
      {"ball_on_table.bin", ballOnTable()}};
  const char* rewrite = std::getenv("FLUIDSOUND_WRITE_CONTACT_SEEDS");
  for (const auto& [name, log] : seeds) {
    if (rewrite != nullptr && std::string(rewrite) == "1") writeContactLog(corpus / name, log);
    EXPECT_EQ(test::fileBytes(corpus / name), encodeContactLog(log)) << name;
    EXPECT_EQ(readContactLog(corpus / name), log) << name;
  }
}

}  // namespace
}  // namespace fluidsound::io
