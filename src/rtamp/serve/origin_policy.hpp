// Who may talk to `rtamp serve` (docs/serve.md "Security"): the `Host` of every
// HTTP request and the `Origin` of every WebSocket handshake, checked before
// anything is served, so that no other web page a user visits can drive the
// episode (cross-site WebSocket hijacking) or read it (DNS rebinding).
//
//  - Host: a request must name this server: the address it listens on, or
//    `localhost` when that address is loopback or every interface, or any IP
//    address when it is every interface (an address in the URL cannot be
//    rebound to another machine), or the host of an allowed origin. The port
//    is not checked (the connection came to ours; a forwarded port differs).
//  - Origin (WebSocket only; GET requests change nothing and a browser keeps
//    their answers from other origins): none (a program, not a browser page)
//    is allowed; otherwise it must be the page's own origin — http://HOST
//    exactly as the request's accepted Host, or, among loopback names
//    (localhost, 127.0.0.1, [::1]), the same port — or one the user allowed
//    (--allow-origin). `null`, `file://` and every other origin are refused.
// Invariants: every check returns "" (allowed) or one short line saying why
// not; nothing a client sends is quoted beyond a short excerpt.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtamp::serve {

// scheme://host:port, lower-case, the port always given (80 / 443 by default).
struct Origin {
  std::string scheme, host;  // host: a name, an IPv4 address or [an IPv6 address]
  unsigned port = 0;
  std::string text() const;  // "http://localhost:8080"
  bool operator==(const Origin&) const = default;
};

// An origin as browsers send it and users write it: http or https, a host, an
// optional port, nothing after it but an optional "/". Nullopt otherwise, with
// `why` (when given) saying what is wrong ("'x' is not an origin: no scheme ...").
std::optional<Origin> parse_origin(std::string_view text, std::string* why = nullptr);

class OriginPolicy {
 public:
  // `address`: the address listened on (an IP address, as Server binds it);
  // `allowed`: origins besides the page's own (parsed by parse_origin).
  OriginPolicy(const std::string& address, std::vector<Origin> allowed = {});

  // Why a request with this Host header (absent: nullopt) is refused, or "".
  std::string refuse_host(std::optional<std::string_view> host) const;
  // Why a WebSocket handshake with this Origin (absent: nullopt) is refused, or
  // "", for a request whose `host` passed refuse_host.
  std::string refuse_origin(std::optional<std::string_view> origin, std::string_view host) const;

  // The names a Host may have, for messages and docs ("127.0.0.1, localhost").
  std::string names() const;

 private:
  bool own_name(const std::string& host) const;

  std::string address_;  // as in a URL: 127.0.0.1, [::1]
  bool loopback_ = false, any_ = false;
  std::vector<Origin> allowed_;
};

}  // namespace rtamp::serve
