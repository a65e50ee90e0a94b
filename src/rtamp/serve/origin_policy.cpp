#include "rtamp/serve/origin_policy.hpp"

#include <algorithm>
#include <cctype>

#include <boost/asio/ip/address.hpp>

#include "rtamp/util/format.hpp"

namespace rtamp::serve {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// What a client sent, as a message may quote it: control bytes escaped, at most 60 bytes.
std::string excerpt(std::string_view text) {
  constexpr std::size_t kMax = 60;
  if (text.size() <= kMax) return "'" + escape_text(text) + "'";
  return "'" + escape_text(text.substr(0, kMax)) + "...' (" + std::to_string(text.size()) + " bytes)";
}

bool is_ip(std::string_view host) {
  boost::system::error_code ec;
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') {
    const auto a = boost::asio::ip::make_address(std::string(host.substr(1, host.size() - 2)), ec);
    return !ec && a.is_v6();
  }
  const auto a = boost::asio::ip::make_address(std::string(host), ec);
  return !ec && a.is_v4();
}

// A DNS name: labels of letters, digits and '-' (not at either end), 1-63 bytes each.
bool is_name(std::string_view host) {
  if (host.empty() || host.size() > 253) return false;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = host.find('.', start);
    const std::string_view label = host.substr(start, dot == std::string_view::npos ? host.npos : dot - start);
    if (label.empty() || label.size() > 63 || label.front() == '-' || label.back() == '-') return false;
    for (const char c : label)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') return false;
    if (dot == std::string_view::npos) return true;
    start = dot + 1;
  }
}

bool is_loopback_name(const std::string& host) {
  if (host == "localhost") return true;
  boost::system::error_code ec;
  const std::string bare = host.size() > 2 && host.front() == '[' ? host.substr(1, host.size() - 2) : host;
  const auto a = boost::asio::ip::make_address(bare, ec);
  return !ec && a.is_loopback();
}

// "host[:port]" (host a name, IPv4 or [IPv6]) into a lower-case host and the
// port (`default_port` when absent); false when it is not that.
bool split_host_port(std::string_view text, unsigned default_port, std::string& host, unsigned& port) {
  std::size_t end = 0;
  if (!text.empty() && text.front() == '[') {
    end = text.find(']');
    if (end == std::string_view::npos) return false;
    ++end;
  } else {
    end = std::min(text.find(':'), text.size());
  }
  host = lower(text.substr(0, end));
  const std::string_view rest = text.substr(end);
  port = default_port;
  if (!rest.empty()) {
    if (rest.front() != ':' || rest.size() < 2 || rest.size() > 6) return false;
    unsigned p = 0;
    for (const char c : rest.substr(1)) {
      if (!std::isdigit(static_cast<unsigned char>(c))) return false;
      p = p * 10 + static_cast<unsigned>(c - '0');
    }
    if (p == 0 || p > 65535) return false;
    port = p;
  }
  return is_ip(host) || is_name(host);
}

}  // namespace

std::string Origin::text() const { return scheme + "://" + host + ":" + std::to_string(port); }

std::optional<Origin> parse_origin(std::string_view text, std::string* why) {
  auto fail = [&](const std::string& what) -> std::optional<Origin> {
    if (why) *why = excerpt(text) + " is not an origin: " + what + " (an origin is http://HOST[:PORT] or https://HOST[:PORT], e.g. http://lab.example:8000)";
    return std::nullopt;
  };
  const std::size_t colon = text.find("://");
  if (colon == std::string_view::npos) return fail("no scheme");
  Origin o;
  o.scheme = lower(text.substr(0, colon));
  if (o.scheme != "http" && o.scheme != "https") return fail("the scheme '" + escape_text(o.scheme.substr(0, 20)) +
                                                             "' is not http or https");
  std::string_view rest = text.substr(colon + 3);
  if (!rest.empty() && rest.back() == '/') rest.remove_suffix(1);
  if (rest.empty()) return fail("no host");
  if (rest.find_first_of("/?#@") != std::string_view::npos) return fail("an origin has no path, query or user");
  if (!split_host_port(rest, o.scheme == "https" ? 443 : 80, o.host, o.port))
    return fail("no valid HOST[:PORT] (a name, an IPv4 address or [an IPv6 one]; a port in 1-65535)");
  return o;
}

OriginPolicy::OriginPolicy(const std::string& address, std::vector<Origin> allowed) : allowed_(std::move(allowed)) {
  boost::system::error_code ec;
  const auto a = boost::asio::ip::make_address(address, ec);
  address_ = !ec && a.is_v6() ? "[" + a.to_string() + "]" : ec ? lower(address) : a.to_string();
  loopback_ = !ec && a.is_loopback();
  any_ = !ec && a.is_unspecified();
}

bool OriginPolicy::own_name(const std::string& host) const {
  if (host == address_) return true;
  if ((loopback_ || any_) && host == "localhost") return true;
  return any_ && is_ip(host);
}

std::string OriginPolicy::names() const {
  std::vector<std::string> all{any_ ? "any IP address of this machine" : address_};
  if (loopback_ || any_) all.push_back("localhost");
  for (const Origin& o : allowed_)
    if (!own_name(o.host) && std::find(all.begin(), all.end(), o.host) == all.end()) all.push_back(o.host);
  std::string s;
  for (const std::string& n : all) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string OriginPolicy::refuse_host(std::optional<std::string_view> host) const {
  if (!host) return "a request needs a Host header";
  std::string name;
  unsigned port = 0;
  if (!split_host_port(*host, 80, name, port)) return "the Host header " + excerpt(*host) + " is not host[:port]";
  if (own_name(name)) return "";
  for (const Origin& o : allowed_)
    if (o.host == name) return "";
  return "Host " + excerpt(*host) + " is not a name of this server (" + names() +
         "; --allow-origin adds one)";
}

std::string OriginPolicy::refuse_origin(std::optional<std::string_view> origin, std::string_view host) const {
  if (!origin) return "";  // not a browser page: nothing to hijack
  const std::string refused = "Origin " + excerpt(*origin) +
                              " may not use this server: only its own page's origin, or one given with --allow-origin";
  const std::optional<Origin> o = parse_origin(*origin);
  if (!o) return refused;
  if (std::find(allowed_.begin(), allowed_.end(), *o) != allowed_.end()) return "";
  std::string name;
  unsigned port = 0;
  if (o->scheme != "http" || !split_host_port(host, 80, name, port) || o->port != port) return refused;
  if (o->host == name || (is_loopback_name(o->host) && is_loopback_name(name))) return "";
  return refused;
}

}  // namespace rtamp::serve
