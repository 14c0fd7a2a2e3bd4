#include "local_hosts.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>

namespace pgamesh::viewer {

namespace {

// Host names are case-insensitive (RFC 9110 4.2.3).
std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// "::1" -> "[::1]": an IPv6 address is written in brackets in Host and Origin.
std::string host_name_for_url(const std::string& host) {
  return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

}  // namespace

bool is_loopback_host(std::string_view host) {
  std::string h = lower(host);
  if (h == "localhost") return true;
  if (h.size() > 2 && h.front() == '[' && h.back() == ']') h = h.substr(1, h.size() - 2);
  // Addresses only, parsed: a name like "127.example.com" may resolve anywhere.
  in_addr v4{};
  if (inet_pton(AF_INET, h.c_str(), &v4) == 1) return (ntohl(v4.s_addr) >> 24) == 127;
  in6_addr v6{};
  return inet_pton(AF_INET6, h.c_str(), &v6) == 1 && IN6_IS_ADDR_LOOPBACK(&v6);
}

bool is_wildcard_host(std::string_view host) {
  return host == "0.0.0.0" || host == "::" || host == "[::]";
}

HostCheck host_check_for(const std::string& bound_host, int port, bool allow_remote) {
  HostCheck check;
  check.any_host = allow_remote && is_wildcard_host(bound_host);
  const std::string suffix = ":" + std::to_string(port);
  for (const std::string& name : {std::string("127.0.0.1"), std::string("localhost"),
                                  std::string("[::1]"), lower(host_name_for_url(bound_host))})
    check.hosts.push_back(name + suffix);
  return check;
}

bool host_allowed(const HostCheck& check, std::string_view host_header) {
  if (check.any_host) return true;
  const std::string host = lower(host_header);
  return std::find(check.hosts.begin(), check.hosts.end(), host) != check.hosts.end();
}

bool origin_is_own(std::string_view origin, std::string_view host_header) {
  return lower(origin) == "http://" + lower(host_header);
}

}  // namespace pgamesh::viewer
