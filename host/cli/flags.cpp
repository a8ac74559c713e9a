// flags.cpp -- checks every subcommand's flags share (commands.h).
#include "cli/commands.h"

#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>

#include <cctype>
#include <cstring>
#include <filesystem>

namespace lb::cli {

namespace fs = std::filesystem;

namespace {

// "FLOAT", "INT", "UINT", ... as CLI11 names an option's value type, with
// ":<validator>" appended for each check it has.
bool numericType(const std::string& type)
{
    for (const char* t : {"FLOAT", "INT", "UINT", "NUMBER"})
        if (type.rfind(t, 0) == 0 && (type.size() == std::strlen(t) || type[std::strlen(t)] == ':')) return true;
    return false;
}

// Empty when `s` is a plain decimal number (the whole text), else the complaint.
std::string strictDecimal(const std::string& s, bool integer)
{
    if (s.empty()) return "expected a number, got an empty value";
    // nan and inf pass here: the flag's range check refuses them, naming its range
    std::string lower;
    for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!integer && (lower == "nan" || lower == "inf" || lower == "+inf" || lower == "-inf")) return "";
    // hex (0x10), binary (0b1), octal (0o7), nan, inf, digit separators: CLI11 takes them all
    const char* allowed = integer ? "+-0123456789" : "+-0123456789.eE";
    if (s.find_first_not_of(allowed) != std::string::npos)
        return fmt::format("expected a decimal {}, got '{}'", integer ? "integer" : "number", s);
    try {
        util::parseReal("", s);
    } catch (const InputError&) {
        return fmt::format("expected a decimal {}, got '{}'", integer ? "integer" : "number", s);
    }
    return "";
}

}  // namespace

void strictNumericFlags(CLI::App& app)
{
    for (CLI::Option* opt : app.get_options()) {
        const std::string type = opt->get_type_name();
        if (!numericType(type)) continue;
        const bool integer = type.rfind("FLOAT", 0) != 0 && type.rfind("NUMBER", 0) != 0;
        opt->check(CLI::Validator([integer](std::string& s) { return strictDecimal(s, integer); }, "", "decimal"));
    }
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) strictNumericFlags(*sub);
}

CLI::Validator outFilePath()
{
    return CLI::Validator(
        [](std::string& s) -> std::string {
            if (s.empty()) return "expected a file path, got an empty value";
            if (s.back() == '/') return fmt::format("expected a file path, got the directory path '{}'", s);
            std::error_code ec;
            fs::file_status st = fs::status(s, ec);
            if (!ec && fs::exists(st) && !fs::is_regular_file(st))
                return fmt::format("expected a regular file path, got '{}', which is {}", s,
                                   fs::is_directory(st) ? "a directory" : "a device, FIFO or socket");
            return "";
        },
        "", "output file");
}

CLI::Validator outDirPath()
{
    return CLI::Validator(
        [](std::string& s) -> std::string {
            if (s.empty()) return "expected a directory path, got an empty value";
            std::error_code ec;
            fs::file_status st = fs::status(s, ec);
            if (!ec && fs::exists(st) && !fs::is_directory(st))
                return fmt::format("expected a directory path, got '{}', which is not a directory", s);
            return "";
        },
        "", "output directory");
}

}  // namespace lb::cli
