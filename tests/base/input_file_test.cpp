// base/input_file.h: only regular files are read, never more than a kind's limit, and
// messages stay one line.
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/atomic_file.h"
#include "base/input_file.h"

namespace pw {
namespace {
namespace fs = std::filesystem;

class InputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pw_input_file_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, size_t bytes) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << std::string(bytes, 'x');
    return path;
  }
  fs::path dir_;
};

constexpr InputKind kSmall{"thing", 100};

TEST_F(InputFileTest, ReadsARegularFileUpToItsLimitExactly) {
  auto at = readInputFile(file("at.txt", 100), kSmall);
  ASSERT_TRUE(at) << at.message();
  EXPECT_EQ(at->size(), 100u);
  auto over = readInputFile(file("over.txt", 101), kSmall);
  ASSERT_FALSE(over);
  EXPECT_NE(over.message().find("over.txt: the thing is 101 bytes, more than the 100 bytes photowalk reads for a thing"),
            std::string::npos)
      << over.message();
}

TEST_F(InputFileTest, RefusesAFifoWithoutOpeningIt) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Opened, this would block for ever (no writer): the test would hang, not fail.
  for (auto result : {readInputFile(fifo, kModelInput), readFile(fifo)}) {
    ASSERT_FALSE(result);
    EXPECT_NE(result.message().find("pipe: is a FIFO (named pipe), not a file"), std::string::npos) << result.message();
  }
  EXPECT_FALSE(checkInputFile(fifo, kPhotoInput));
}

TEST_F(InputFileTest, RefusesDevicesFoldersAndSockets) {
  for (const char* device : {"/dev/zero", "/dev/urandom", "/dev/null"}) {
    auto result = readInputFile(device, kTextureInput);
    ASSERT_FALSE(result) << device;
    EXPECT_NE(result.message().find(std::string(device) + ": is a character device, not a file"), std::string::npos)
        << result.message();
  }
  auto folder = readInputFile(dir_, kShotInput);
  ASSERT_FALSE(folder);
  EXPECT_NE(folder.message().find(": is a folder, not a file; photowalk reads a shot only from a regular file"),
            std::string::npos)
      << folder.message();

  const fs::path socketPath = dir_ / "sock";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::snprintf(address.sun_path, sizeof address.sun_path, "%s", socketPath.c_str());
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  auto socket = readInputFile(socketPath, kLayoutInput);
  ::close(fd);
  ASSERT_FALSE(socket);
  EXPECT_NE(socket.message().find("sock: is a socket, not a file"), std::string::npos) << socket.message();
}

TEST_F(InputFileTest, FollowsLinksToRegularFilesButNotToFifos) {
  const fs::path target = file("target.txt", 5);
  fs::create_symlink(target, dir_ / "link.txt");
  auto linked = readInputFile(dir_ / "link.txt", kSmall);
  ASSERT_TRUE(linked) << linked.message();
  EXPECT_EQ(*linked, "xxxxx");
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  fs::create_symlink(dir_ / "pipe", dir_ / "pipe_link");
  auto piped = readInputFile(dir_ / "pipe_link", kSmall);
  ASSERT_FALSE(piped);
  EXPECT_NE(piped.message().find("FIFO"), std::string::npos) << piped.message();
  fs::create_symlink(dir_ / "nothing", dir_ / "dangling");
  auto dangling = readInputFile(dir_ / "dangling", kSmall);
  ASSERT_FALSE(dangling);
  EXPECT_NE(dangling.message().find("a link to nothing"), std::string::npos) << dangling.message();
  auto missing = readInputFile(dir_ / "missing", kSmall);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.message().find("missing: no such file"), std::string::npos) << missing.message();
}

TEST_F(InputFileTest, EachKindStatesItsLimit) {
  EXPECT_EQ(formatBytes(kPhotoInput.maxBytes), "512 MiB");
  EXPECT_EQ(formatBytes(kModelInput.maxBytes), "1 GiB");
  EXPECT_EQ(formatBytes(kTextureInput.maxBytes), "256 MiB");
  EXPECT_EQ(formatBytes(kBufferInput.maxBytes), "1 GiB");
  EXPECT_EQ(formatBytes(kShotInput.maxBytes), "16 MiB");
  EXPECT_EQ(formatBytes(kLayoutInput.maxBytes), "16 MiB");
  EXPECT_EQ(formatBytes(1536 * 1024), "1.5 MiB");
  // A shot of exactly its limit is read; one byte more is refused by its size (a
  // sparse file: nothing is written but the length).
  const fs::path at = dir_ / "at.json", over = dir_ / "over.json";
  std::ofstream(at).close();
  std::ofstream(over).close();
  fs::resize_file(at, kShotInput.maxBytes);
  fs::resize_file(over, kShotInput.maxBytes + 1);
  EXPECT_TRUE(readInputFile(at, kShotInput));
  auto refused = readInputFile(over, kShotInput);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.message().find("the shot is 16777217 bytes, more than the 16 MiB photowalk reads for a shot"),
            std::string::npos)
      << refused.message();
}

TEST_F(InputFileTest, InsideFoldersResolvesDotDotAndLinks) {
  fs::create_directories(dir_ / "model" / "sub");
  fs::create_directories(dir_ / "modelx");
  const fs::path secret = file("secret.txt", 3);
  const std::vector<fs::path> model{dir_ / "model"};
  EXPECT_TRUE(insideFolders(dir_ / "model" / "tex.png", model));  // need not exist
  EXPECT_TRUE(insideFolders(dir_ / "model" / "sub" / ".." / "tex.png", model));
  EXPECT_TRUE(insideFolders(dir_ / "model" / "sub" / "deeper" / "x.wrl", model));
  EXPECT_FALSE(insideFolders(dir_ / "model" / ".." / "secret.txt", model));
  EXPECT_FALSE(insideFolders(dir_ / "modelx" / "a.png", model));
  EXPECT_FALSE(insideFolders("/etc/passwd", model));
  fs::create_symlink(secret, dir_ / "model" / "link.txt");  // inside by name, outside in fact
  EXPECT_FALSE(insideFolders(dir_ / "model" / "link.txt", model));
  EXPECT_TRUE(insideFolders(secret, {dir_ / "model", dir_}));  // a folder a person named
  EXPECT_TRUE(insideFolders(dir_ / "model" / "a.png", {dir_ / "model" / ""}));
  EXPECT_FALSE(insideFolders(dir_ / "model" / "a.png", {}));
}

TEST(EscapeControls, KeepsAMessageOnOneLine) {
  EXPECT_EQ(escapeControls("plain text, a\\b"), "plain text, a\\b");
  EXPECT_EQ(escapeControls(std::string("a\nb\rc\td\0e\x1b" "f\x7f", 12)), "a\\nb\\rc\\td\\0e\\x1bf\\x7f");
  EXPECT_EQ(escapeControls("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 stays as it is
  // A path with a newline, refused: the message has none.
  auto result = readInputFile("no\nsuch", kSmall);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.message().find('\n'), std::string::npos) << result.message();
}

}  // namespace
}  // namespace pw
