// magnus: 2D potential flow past a spinning cylinder. The subcommands live in app/cmd_*.cpp.
#include <cstdio>
#include <exception>

#include "app/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"magnus: potential flow past a spinning cylinder (Magnus lift, Kutta–Joukowski, the seed estimate)"};
  app.set_version_flag("--version", std::string("magnus ") + MAGNUS_VERSION);
  app.require_subcommand(1);
  magnus::add_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "magnus: %s (see magnus --help)\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "magnus: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
