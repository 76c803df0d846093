// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/cyclictest_command.h"

#include <cctype>
#include <charconv>
#include <stdexcept>

#include "headroom/command_load.h"
#include "headroom/text_lines.h"
#include "util/text.h"

namespace bs::headroom_import {

std::int64_t CyclictestCommand::period_ns(int index) const {
  const std::int64_t distance = histogram_bins ? 0 : distance_us;
  return (static_cast<std::int64_t>(interval_us) + index * distance) * 1000;
}

int CyclictestCommand::priority_of(int index) const {
  if (!priospread) return priority;
  return priority - index > 0 ? priority - index : 0;
}

std::vector<std::string> shell_words(std::string_view line) {
  try {
    return headroom::split_command(std::string(line));
  } catch (const std::invalid_argument&) {
    // An unclosed quote (a command line rt-tests wrote unescaped, a cut paste): blanks alone separate.
    std::vector<std::string> words;
    for (std::string_view w : headroom_import::words_of(line)) words.emplace_back(w);
    return words;
  }
}

namespace {

// atoi as cyclictest uses it: the leading digits, 0 when there are none.
int leading_int(std::string_view s) {
  int value = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  (void)ptr;
  return ec == std::errc() ? value : 0;
}

bool names_cyclictest(std::string_view word) {
  const auto slash = word.rfind('/');
  if (slash != std::string_view::npos) word.remove_prefix(slash + 1);
  return word == "cyclictest";
}

std::string policy_name(std::string_view value) {
  // handlepolicy() compares prefixes case-insensitively and falls back to SCHED_OTHER.
  const std::string v = lower(value);
  if (v.starts_with("fifo")) return "SCHED_FIFO";
  if (v.starts_with("rr")) return "SCHED_RR";
  if (v.starts_with("batch")) return "SCHED_BATCH";
  if (v.starts_with("idle")) return "SCHED_IDLE";
  return "SCHED_OTHER";
}

// Short options that take a value (getopt string "a::A::b:c:d:D:F:h:H:i:l:MNo:p:mqrRsSt::uvD:x"); a, A and t take
// one only when attached (cyclictest then also looks at the next word for -a / -t, handled below).
bool short_takes_value(char c) {
  switch (c) {
    case 'b':
    case 'c':
    case 'd':
    case 'D':
    case 'F':
    case 'h':
    case 'H':
    case 'i':
    case 'l':
    case 'o':
    case 'p':
      return true;
    default:
      return false;
  }
}

class CommandReader {
 public:
  explicit CommandReader(CyclictestCommand* cmd) : cmd_(cmd) {}

  void option(std::string_view name, std::optional<std::string_view> value, const std::vector<std::string>& words,
              std::size_t* next) {
    // A long option's or an optional short option's value may be the next word when it looks like one.
    const auto take_next_numeric = [&]() -> std::optional<std::string_view> {
      if (value) return value;
      if (*next < words.size() && !words[*next].empty() &&
          (std::isdigit(static_cast<unsigned char>(words[*next][0])) != 0)) {
        return std::string_view(words[(*next)++]);
      }
      return std::nullopt;
    };
    const auto required = [&]() -> std::string_view {
      if (value) return *value;
      if (*next < words.size()) return words[(*next)++];
      return {};
    };
    if (name == "i" || name == "interval") {
      cmd_->interval_us = leading_int(required());
    } else if (name == "d" || name == "distance") {
      cmd_->distance_us = leading_int(required());
    } else if (name == "h" || name == "histogram") {
      cmd_->histogram_bins = leading_int(required());
    } else if (name == "H" || name == "histofall") {
      cmd_->histofall = true;
      cmd_->histogram_bins = leading_int(required());
    } else if (name == "N" || name == "nsecs") {
      cmd_->nsecs = true;
    } else if (name == "p" || name == "priority") {
      cmd_->priority = leading_int(required());
      if (policy_ != "SCHED_FIFO" && policy_ != "SCHED_RR") policy_ = "SCHED_FIFO";
    } else if (name == "policy") {
      policy_ = policy_name(required());
    } else if (name == "priospread") {
      cmd_->priospread = true;
    } else if (name == "m" || name == "mlockall") {
      cmd_->mlockall = true;
    } else if (name == "q" || name == "quiet") {
      cmd_->quiet = true;
    } else if (name == "t" || name == "threads") {
      const auto v = take_next_numeric();
      cmd_->threads = v ? std::optional<int>(leading_int(*v)) : std::nullopt;
    } else if (name == "S" || name == "smp") {
      cmd_->threads.reset();
      cmd_->affinity = "all";
    } else if (name == "a" || name == "affinity") {
      const auto v = take_next_numeric();
      cmd_->affinity = v ? std::string(*v) : "all";
    } else if (short_takes_value(name.size() == 1 ? name[0] : '\0') || name == "duration" || name == "loops" ||
               name == "breaktrace" || name == "clock" || name == "fifo" || name == "oscope" || name == "json" ||
               name == "histfile" || name == "latency" || name == "mainaffinity" || name == "spike" ||
               name == "spike-nodes") {
      (void)required();  // a value this reader does not need
    }
  }

  void finish() {
    // process_options(): a priority without a real-time policy becomes SCHED_FIFO; a real-time policy without a
    // priority gets threads + 1; otherwise the threads run SCHED_OTHER.
    if (policy_.empty()) policy_ = cmd_->priority > 0 ? "SCHED_FIFO" : "SCHED_OTHER";
    if (cmd_->priority > 0 && policy_ != "SCHED_FIFO" && policy_ != "SCHED_RR") policy_ = "SCHED_FIFO";
    if ((policy_ == "SCHED_FIFO" || policy_ == "SCHED_RR") && cmd_->priority == 0 && cmd_->threads)
      cmd_->priority = *cmd_->threads + 1;
    cmd_->policy = policy_;
  }

 private:
  CyclictestCommand* cmd_;
  std::string policy_;
};

}  // namespace

std::optional<CyclictestCommand> parse_cyclictest_command(std::string_view line) {
  const std::vector<std::string> words = shell_words(line);
  std::size_t i = 0;
  while (i < words.size() && !names_cyclictest(words[i])) ++i;
  if (i == words.size()) return std::nullopt;
  CyclictestCommand cmd;
  cmd.text = std::string(line.substr(line.find(words[i]) == std::string_view::npos ? 0 : line.find(words[i])));
  CommandReader reader(&cmd);
  for (std::size_t next = i + 1; next < words.size();) {
    const std::string& w = words[next++];
    // The command ends at a pipe, a list or a redirection ("cyclictest ... -q | tee out.txt").
    if (w == "|" || w == "||" || w == "&&" || w == ";" || w == "&" || w.starts_with(">") || w.starts_with("2>")) break;
    if (w.starts_with("--") && w.size() > 2) {
      const auto eq = w.find('=');
      const std::string_view name = std::string_view(w).substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
      std::optional<std::string_view> value;
      if (eq != std::string::npos) value = std::string_view(w).substr(eq + 1);
      reader.option(name, value, words, &next);
    } else if (w.starts_with("-") && w.size() > 1) {
      for (std::size_t k = 1; k < w.size(); ++k) {
        const char c = w[k];
        const std::string name(1, c);
        if (short_takes_value(c) || c == 'a' || c == 'A' || c == 't') {
          std::optional<std::string_view> value;
          if (k + 1 < w.size()) value = std::string_view(w).substr(k + 1);
          reader.option(name, value, words, &next);
          break;  // the rest of the word was the value
        }
        reader.option(name, std::nullopt, words, &next);
      }
    }
    // A bare word (a stray argument, a shell redirection) is ignored, as getopt leaves it for the program.
  }
  reader.finish();
  return cmd;
}

}  // namespace bs::headroom_import
