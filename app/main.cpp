// magnus: 2D flow past a spinning cylinder (potential flow and laminar Navier–Stokes). The subcommands live in app/cmd_*.cpp.
#include <cstdio>
#include <exception>
#include <string>

#include "app/commands.hpp"
#include "app/run_viscous.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "magnus: flow past a spinning cylinder: potential flow (Magnus lift, Kutta–Joukowski, the seed "
      "estimate) and 2D laminar Navier–Stokes (model.flow = \"navier-stokes\": drag, shedding, S(Re, α))"};
  app.set_version_flag("--version", std::string("magnus ") + MAGNUS_VERSION);
  app.require_subcommand(1);
  magnus::add_commands(app);
  // An unknown first word is an unknown command (CLI11 would only say that a subcommand is required).
  std::string list;
  bool known = false;
  for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    list += (list.empty() ? "" : ", ") + sub->get_name();
    known = known || (argc >= 2 && sub->get_name() == argv[1]);
  }
  if (argc >= 2 && argv[1][0] != '-' && !known) {
    std::fprintf(stderr, "magnus: unknown command '%s' (commands: %s; see magnus --help)\n", argv[1],
                 list.c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const magnus::Interrupted& e) {
    std::fflush(stdout);
    return 128 + e.signal;  // a run cut short by a signal: its partial result and checkpoint are written
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "magnus: %s (see magnus --help)\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "magnus: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
