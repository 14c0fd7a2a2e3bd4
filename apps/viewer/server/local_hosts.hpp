// Which requests come from pages of this machine's server. A web page elsewhere can point its own
// DNS name at 127.0.0.1 (DNS rebinding) and then read the API as same-origin; the Host header it
// sends still names its own site, so the server answers only the names it is reached by. Forms and
// scripts of other sites can POST to it without rebinding; their Origin header names their site.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pgamesh::viewer {

struct HostCheck {
  std::vector<std::string> hosts;  // accepted Host header values, "name:port"
  bool any_host = false;           // a wildcard address served with --allow-remote
};

/// 127.0.0.0/8, ::1 or localhost: an address only this machine reaches.
bool is_loopback_host(std::string_view host);

/// 0.0.0.0 or ::, every address of the machine.
bool is_wildcard_host(std::string_view host);

/// The Host values a server bound to `bound_host`:`port` accepts: 127.0.0.1, localhost and [::1]
/// with the port, and the bound address; any Host when a wildcard address is served remotely.
HostCheck host_check_for(const std::string& bound_host, int port, bool allow_remote);

/// Whether a request with this Host header is answered.
bool host_allowed(const HostCheck& check, std::string_view host_header);

/// Whether an Origin header names the server the request was sent to (its accepted Host).
bool origin_is_own(std::string_view origin, std::string_view host_header);

}  // namespace pgamesh::viewer
