#include "serve_help.hpp"

namespace pgamesh::cli {

void print_serve_help(std::FILE* out) {
  std::fprintf(out,
               "usage: pgamesh serve [FILE...] [options]\n"
               "\n"
               "Starts the viewer: a local web page showing meshes, their mass properties and\n"
               "fuel, with a JSON API. Open the printed URL in a browser. Ctrl-C stops it.\n"
               "FILEs named here are read at start-up and listed on the page beside the bundled\n"
               "meshes.\n"
               "\n"
               "options:\n"
               "  --port P          TCP port (default 8080; 0 picks a free one)\n"
               "  --host H          address to bind (default 127.0.0.1, this machine only);\n"
               "                    another address needs --allow-remote\n"
               "  --allow-remote    accept a --host other machines can reach (no authentication)\n"
               "  --max-upload N    largest accepted upload in bytes, suffix K, M or G allowed\n"
               "                    (default 64M)\n"
               "  --weld-tolerance T  analyse every mesh welded within T (an upload may give\n"
               "                    its own: POST /api/upload?weld_tolerance=T)\n"
               "  --head-timeout S  seconds a request's line and headers may take to arrive,\n"
               "                    counted from the connection or the previous answer\n"
               "                    (default 10)\n"
               "  --request-timeout S  seconds a request's body and answer may take after its\n"
               "                    headers (default 60); a connection over either is closed\n"
               "  --assets DIR      folder of the page (default: <prefix>/share/pgamesh/web when\n"
               "                    installed, else the source tree's apps/viewer/web)\n"
               "  --quiet           do not log each request on stderr\n");
}

}  // namespace pgamesh::cli
