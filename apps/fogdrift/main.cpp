// fogdrift: start-up temperature-drift compensation for fiber-optic gyroscopes.
#include "app.hpp"

int main(int argc, char** argv) {
  return fogdrift::app::run(argc, argv);
}
