#pragma once
// A bad case file: which file, which line, which key, what was expected, what was found.
// The program prints what() and exits with status 2.
#include <stdexcept>
#include <string>

namespace pilempm::io {

class CaseError : public std::runtime_error {
public:
    CaseError(const std::string& file, int line, const std::string& key,
              const std::string& expected, const std::string& found)
        : std::runtime_error(format(file, line, key, expected, found)) {}

private:
    static std::string format(const std::string& file, int line, const std::string& key,
                              const std::string& expected, const std::string& found) {
        std::string s = file;
        if (line > 0) s.append(":").append(std::to_string(line));
        s.append(": ").append(key.empty() ? "(document)" : key).append(": expected ").append(expected);
        if (!found.empty()) s.append(", found ").append(found);
        return s;
    }
};

}  // namespace pilempm::io
