#include "gnuplot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_error.hpp"

namespace cwcli {

bool gnuplot_available()
{
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string exe = (dir.empty() ? "." : dir) + "/gnuplot";
        if (access(exe.c_str(), X_OK) == 0) return true;
    }
    return false;
}

namespace {

std::string first_error_line(const std::string& log_path)
{
    std::ifstream log(log_path);
    std::string line, first;
    while (std::getline(log, line)) {
        if (first.empty() && !line.empty()) first = line;
        if (line.find("rror") != std::string::npos) return line;
    }
    return first.empty() ? "no message" : first;
}

} // namespace

void run_gnuplot(const std::string& dir, const std::string& script, const std::string& text)
{
    std::ofstream file(dir + "/" + script);
    file << text;
    file.close();
    if (!file) throw CliError(kExitFailure, "cannot write " + dir + "/" + script);
    const std::string log_path = dir + "/gnuplot/gnuplot.log";
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) throw CliError(kExitFailure, "cannot start gnuplot (fork failed)");
    if (pid == 0) {
        // Child: only async-signal-safe calls until exec.
        if (chdir(dir.c_str()) != 0) _exit(126);
        const int fd = open("gnuplot/gnuplot.log", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {}
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        const std::string why = WIFEXITED(status) && WEXITSTATUS(status) == 127
                                    ? "gnuplot could not be executed"
                                    : first_error_line(log_path);
        throw CliError(kExitFailure, "gnuplot failed on " + script + ": " + why);
    }
    std::error_code ec;
    if (std::filesystem::file_size(log_path, ec) == 0 && !ec) std::filesystem::remove(log_path, ec);
}

void gp_data_row(std::ostream& out, const double* row, size_t n,
                 std::vector<std::vector<double>>& cols)
{
    char buf[40];
    for (size_t c = 0; c < n; ++c) {
        std::snprintf(buf, sizeof buf, c ? " %.9g" : "%.9g", row[c]);
        out << buf;
        cols[c].push_back(row[c]);
    }
    out << "\n";
}

std::string gp_quote(const std::string& text)
{
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string gp_text_lines(const std::vector<std::string>& lines)
{
    std::string out = "\"";
    for (size_t k = 0; k < lines.size(); ++k) {
        if (k) out += "\\n";
        for (char c : lines[k]) {
            if (c == '"' || c == '\\') out += '\\';
            out += c;
        }
    }
    return out + "\"";
}

namespace {

// Characters as drawn: UTF-8 code points, without enhanced-text markup.
size_t drawn_width(const std::string& text)
{
    size_t n = 0;
    for (char ch : text) {
        const unsigned char c = static_cast<unsigned char>(ch);
        n += (c & 0xC0) != 0x80 && c != '_' && c != '^' && c != '{' && c != '}';
    }
    return n;
}

} // namespace

std::string gp_title(const std::vector<std::string>& lines, int width_px, int font_pt)
{
    const size_t limit = static_cast<size_t>((width_px - 40) / (0.7 * font_pt));
    std::vector<std::string> out;
    for (std::string rest : lines) {
        while (drawn_width(rest) > limit) {
            // The longest head that fits, cut after a separator.
            size_t cut = std::string::npos;
            for (const char* separator : {"; ", ", ", " "}) {
                for (size_t at = rest.find(separator); at != std::string::npos;
                     at = rest.find(separator, at + 1)) {
                    const size_t end = at + std::string(separator).size() - 1;
                    if (drawn_width(rest.substr(0, end)) > limit) break;
                    cut = end;
                }
                if (cut != std::string::npos) break;
            }
            if (cut == std::string::npos) break; // one long word: left whole
            out.push_back(rest.substr(0, cut));
            rest = rest.substr(cut + 1);
        }
        out.push_back(rest);
    }
    return gp_text_lines(out);
}

std::string gp_png(const std::string& file, int width, int height)
{
    std::ostringstream s;
    s << "set terminal pngcairo size " << width << "," << height
      << " enhanced font 'DejaVu Sans,10'\nset output " << gp_quote(file) << "\n";
    return s.str();
}

std::string gp_colour_scale(const std::vector<double>& values, const std::string& label)
{
    double lo = 0.0, hi = 0.0;
    for (double v : values) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    std::ostringstream s;
    s.precision(6);
    if (lo >= 0.0) {
        if (!(hi > 0.0)) hi = 1.0;
        s << "set palette defined (0 'white', 0.2 '#fee391', 0.55 '#fe9929', 1 '#8c2d04')\n"
          << "set cbrange [0:" << hi << "]\n";
    } else {
        const double m = std::max(-lo, hi);
        s << "set palette defined (-1 '#2166ac', -0.4 '#92c5de', 0 'white', 0.4 '#f4a582', 1 "
             "'#b2182b')\n"
          << "set cbrange [" << -m << ":" << m << "]\n";
    }
    s << "set cbtics auto\nset cblabel " << gp_quote(label) << " offset 1.5,0\n";
    return s.str();
}

const char* const kPaddedBoxes = "1:2:($3+0.004):($4+0.004)";

std::string gp_state_scale()
{
    return "set palette defined (0 '#c6dbef', 1 '#c6dbef', 1 '#f4a582', 2 '#f4a582')\n"
           "set cbrange [0.5:2.5]\nset cbtics ('adhesion' 1, 'slip' 2) scale 0\nunset cblabel\n";
}

std::string gp_patch_frame(int rolling_direction, const PatchAxes& axes)
{
    // Leading edge where material enters: x = +a when rolling towards +x.
    const int d = rolling_direction >= 0 ? 1 : -1;
    const double a = axes.ax, b = axes.by, cx = axes.cx, cy = axes.cy;
    std::ostringstream s;
    s.precision(9);
    s << "unset arrow; unset label; unset object\n"
      << "set size ratio -1\n"
      << "set xrange [" << cx - 1.12 * a << ":" << cx + 1.12 * a << "]\nset yrange ["
      << cy - 1.12 * b << ":" << cy + 1.42 * b << "]\n";
    if (a == 1.0 && b == 1.0 && cx == 0.0 && cy == 0.0)
        s << "set xtics -1,0.5,1\nset ytics -1,0.5,1\n";
    else
        s << "set xtics auto\nset ytics auto\n";
    s << "set xlabel " << gp_quote(axes.xlabel) << "\nset ylabel " << gp_quote(axes.ylabel) << "\n";
    if (axes.ellipse)
        s << "set object 1 ellipse at " << cx << "," << cy << " size " << 2 * a << "," << 2 * b
          << " front fillstyle empty border lc rgb 'black' lw 1\n";
    s << "set arrow 1 from " << cx - 0.35 * d * a << "," << cy + 1.24 * b << " to "
      << cx + 0.35 * d * a << "," << cy + 1.24 * b
      << " head filled size screen 0.015,25 lw 2 lc rgb 'black' front\n"
      << "set label 1 'rolling' at " << cx << "," << cy + 1.345 * b << " center front\n"
      << "set label 2 'leading edge' at " << cx + 1.08 * d * a << "," << cy + 1.12 * b << " "
      << (d > 0 ? "right" : "left") << " front font ',8'\n"
      << "set label 3 'trailing edge' at " << cx - 1.08 * d * a << "," << cy + 1.12 * b << " "
      << (d > 0 ? "left" : "right") << " front font ',8'\n";
    return s.str();
}

std::string gp_slip_outline(int state_column)
{
    return ", \\\n     '' using ($" + std::to_string(state_column) +
           " == 2 ? $1 : NaN):2:3:4 with boxxyerror lw 0.5 lc rgb '#505050' fs empty border "
           "notitle";
}

} // namespace cwcli
