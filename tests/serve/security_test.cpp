// Who may use `rtamp serve` (serve/origin_policy.hpp, serve/web_root.hpp,
// docs/serve.md "Security"), against a served episode over real sockets: a
// WebSocket handshake from a foreign page (http://evil.example, `null`,
// file://, this host on another port or scheme, another machine's address)
// is refused with 403 and the reason; the page's own origin (127.0.0.1 and
// localhost, either way round), no Origin (a program) and an origin given with
// --allow-origin get the hello. A foreign Host (DNS rebinding: the attacker's
// name for 127.0.0.1), or none, is refused for HTTP and the WebSocket alike;
// with every interface bound, any address is a name of the server but no
// other name is. Files: a symlink in the web root that leads out of it is not
// served (403, nothing of the file sent), one that stays inside is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <boost/beast/http.hpp>

#include "rtamp/serve/origin_policy.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "served_episode.hpp"
#include "ws_client.hpp"

namespace rtamp::serve {
namespace {

using test::Handshake;
using test::Served;
using test::WsClient;
namespace fs = std::filesystem;
namespace http = boost::beast::http;

// GET `target` with this Host header (nullopt: none).
test::HttpAnswer get(unsigned short port, const std::string& target, const std::optional<std::string>& host) {
  return test::http_request(port, http::verb::get, target, host);
}

Origin origin(const std::string& text) {
  const auto o = parse_origin(text);
  EXPECT_TRUE(o) << text;
  return o.value_or(Origin{});
}

LiveOptions paused() {
  LiveOptions o;
  o.episode = test::symbolic_options();
  o.paused = true;
  return o;
}

const world::Scenario& scenario() {
  static const world::Scenario s = world::load_scenario("3-block-tray");
  return s;
}

bool gets_hello(unsigned short port, const Handshake& h, const std::string& address = "127.0.0.1") {
  WsClient c(port, address, h);
  const auto m = c.read();
  return m && (*m)["type"] == "hello";
}

TEST(ServeSecurity, ForeignOriginsCannotOpenTheWebSocket) {
  Served sv(scenario(), paused());
  const std::string own = "127.0.0.1:" + std::to_string(sv.port());
  const std::vector<std::string> foreign = {"http://evil.example", "null", "file://", "http://127.0.0.1:1",
                                            "https://" + own, "http://" + own + ".evil.example",
                                            "http://192.0.2.7:" + std::to_string(sv.port()), std::string(300, 'x')};
  for (const std::string& o : foreign) {
    SCOPED_TRACE(o.substr(0, 80));
    const auto [status, body] = WsClient::declined(sv.port(), {o, std::nullopt});
    EXPECT_EQ(status, 403) << body;
    EXPECT_NE(body.find("Origin '" + o.substr(0, 20)), std::string::npos) << body;
    EXPECT_LT(body.size(), 400u) << "a short excerpt only";
  }
}

TEST(ServeSecurity, ThePagesOwnOriginAndProgramsOpenIt) {
  Served sv(scenario(), paused());
  const std::string port = std::to_string(sv.port());
  EXPECT_TRUE(gets_hello(sv.port(), {}));  // no Origin: a program, not a page
  EXPECT_TRUE(gets_hello(sv.port(), {"http://127.0.0.1:" + port, std::nullopt}));
  EXPECT_TRUE(gets_hello(sv.port(), {"http://localhost:" + port, "localhost:" + port}));
  // The page served as localhost talking to 127.0.0.1, and the other way round.
  EXPECT_TRUE(gets_hello(sv.port(), {"http://localhost:" + port, std::nullopt}));
  EXPECT_TRUE(gets_hello(sv.port(), {"http://127.0.0.1:" + port, "localhost:" + port}));
  // A forwarded port (ssh -L 9000:127.0.0.1:PORT): the page's origin is the Host it used.
  EXPECT_TRUE(gets_hello(sv.port(), {"http://localhost:9000", "localhost:9000"}));
}

TEST(ServeSecurity, AnAllowedOriginOpensItAndItsHostIsServed) {
  ServerOptions so;
  so.allowed_origins = {origin("https://lab.example"), origin("http://Embed.Example:8000/")};
  Served sv(scenario(), paused(), so);
  EXPECT_TRUE(gets_hello(sv.port(), {"https://lab.example", std::nullopt}));
  EXPECT_TRUE(gets_hello(sv.port(), {"https://lab.example:443", std::nullopt}));
  EXPECT_TRUE(gets_hello(sv.port(), {"http://embed.example:8000", std::nullopt}));
  EXPECT_EQ(WsClient::declined(sv.port(), {"https://lab.example:8443", std::nullopt}).first, 403);
  EXPECT_EQ(WsClient::declined(sv.port(), {"http://lab.example", std::nullopt}).first, 403);
  EXPECT_EQ(get(sv.port(), "/api/hello", "lab.example").status, 200);
  EXPECT_EQ(get(sv.port(), "/api/hello", "evil.example").status, 403);
}

TEST(ServeSecurity, ForeignHostsAreRefused) {
  Served sv(scenario(), paused());
  const std::string port = std::to_string(sv.port());
  EXPECT_EQ(get(sv.port(), "/api/hello", "127.0.0.1:" + port).status, 200);
  EXPECT_EQ(get(sv.port(), "/api/hello", "localhost:" + port).status, 200);
  const std::vector<std::optional<std::string>> foreign = {
      "evil.example:" + port, "evil.example", "192.0.2.7:" + port, "localhost.evil.example",
      "127.0.0.1:" + port + "@evil", std::nullopt, ""};
  for (const std::optional<std::string>& host : foreign) {
    SCOPED_TRACE(host.value_or("(no Host)"));
    const test::HttpAnswer a = get(sv.port(), "/api/hello", host);
    EXPECT_EQ(a.status, 403);
    EXPECT_EQ(a.body.find("\"type\""), std::string::npos) << "the hello was sent";
    EXPECT_NE(a.body.find("forbidden"), std::string::npos) << a.body;
    EXPECT_EQ(get(sv.port(), "/", host).status, 403);
  }
  // DNS rebinding: the attacker's page, same-origin with its own name, opens the WebSocket.
  const auto [status, body] = WsClient::declined(sv.port(), {"http://evil.example:" + port, "evil.example:" + port});
  EXPECT_EQ(status, 403);
  EXPECT_NE(body.find("Host 'evil.example:" + port + "' is not a name of this server"), std::string::npos) << body;
}

TEST(ServeSecurity, EveryInterfaceBoundTakesAddressesButNoOtherName) {
  ServerOptions so;
  so.host = "0.0.0.0";
  Served sv(scenario(), paused(), so);
  const std::string port = std::to_string(sv.port());
  EXPECT_EQ(get(sv.port(), "/api/hello", "192.0.2.7:" + port).status, 200);
  EXPECT_EQ(get(sv.port(), "/api/hello", "[2001:db8::7]:" + port).status, 200);
  EXPECT_EQ(get(sv.port(), "/api/hello", "localhost:" + port).status, 200);
  EXPECT_EQ(get(sv.port(), "/api/hello", "evil.example:" + port).status, 403);
  EXPECT_TRUE(gets_hello(sv.port(), {"http://192.0.2.7:" + port, "192.0.2.7:" + port}));
  // A page of another machine's address is not this server's page.
  EXPECT_EQ(WsClient::declined(sv.port(), {"http://192.0.2.99:" + port, "192.0.2.7:" + port}).first, 403);
}

TEST(ServeSecurity, SymlinksOutOfTheWebRootAreNotFollowed) {
  const fs::path dir = test::temp_dir("webroot");
  const fs::path root = dir / "web", outside = dir / "private";
  fs::create_directories(root / "assets");
  fs::create_directories(outside);
  std::ofstream(root / "index.html") << "<html>page</html>";
  std::ofstream(root / "assets" / "main.js") << "// main";
  std::ofstream(outside / "secret.txt") << "SECRET";
  fs::create_symlink(outside / "secret.txt", root / "leak.txt");
  fs::create_symlink(outside, root / "private");
  fs::create_symlink("../../private/secret.txt", root / "assets" / "up.txt");
  fs::create_symlink(root / "assets" / "main.js", root / "alias.js");
  fs::create_symlink(root, dir / "web-link");
  for (const fs::path& web : {root, dir / "web-link"}) {
    SCOPED_TRACE(web.string());
    ServerOptions so;
    so.web_root = web.string();
    Served sv(scenario(), paused(), so);
    EXPECT_TRUE(sv.server.has_page());
    const std::string host = "127.0.0.1:" + std::to_string(sv.port());
    EXPECT_EQ(get(sv.port(), "/", host).body, "<html>page</html>");
    const test::HttpAnswer alias = get(sv.port(), "/alias.js", host);
    EXPECT_EQ(alias.status, 200);
    EXPECT_EQ(alias.body, "// main");
    for (const char* target : {"/leak.txt", "/private/secret.txt", "/assets/up.txt", "/private/"}) {
      SCOPED_TRACE(target);
      const test::HttpAnswer a = get(sv.port(), target, host);
      EXPECT_NE(a.status, 200);
      EXPECT_EQ(a.body.find("SECRET"), std::string::npos);
    }
    EXPECT_EQ(get(sv.port(), "/leak.txt", host).status, 403);
  }
  fs::remove_all(dir);
}

TEST(ServeSecurity, OriginsParseAsBrowsersSendThem) {
  EXPECT_EQ(origin("HTTP://LocalHost").text(), "http://localhost:80");
  EXPECT_EQ(origin("https://lab.example/").text(), "https://lab.example:443");
  EXPECT_EQ(origin("http://[::1]:8080").text(), "http://[::1]:8080");
  for (const char* bad : {"null", "file://", "evil.example", "ftp://x", "http://", "http://a/b", "http://u@a",
                          "http://a:0", "http://a:65536", "http://a:8x", "http://a_b", "http://[::1", "*"}) {
    std::string why;
    EXPECT_FALSE(parse_origin(bad, &why)) << bad;
    EXPECT_EQ(why.rfind(std::string("'") + bad + "' is not an origin: ", 0), 0u) << why;
  }
}

}  // namespace
}  // namespace rtamp::serve
