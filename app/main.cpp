#include "app/commands.h"

int main(int argc, char** argv) { return skylit::app::run_cli(argc, argv); }
