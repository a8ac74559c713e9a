// lumibench methods: the registry's methods and parameters (docs/methods.md
// is its --markdown output).
#include "cli/commands.h"
#include "methods/method_docs.h"

#include <iostream>
#include <memory>

namespace lb::cli {

void addMethodsCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("methods",
                                   "List the methods (name, scenes, summary); --markdown prints "
                                   "docs/methods.md: every method's parameters");
    auto markdown = std::make_shared<bool>(false);
    cmd->add_flag("--markdown", *markdown, "Print the methods and their parameter tables as Markdown");
    cmd->callback([markdown] { std::cout << (*markdown ? methods::methodsMarkdown() : methods::methodsText()); });
}

}  // namespace lb::cli
