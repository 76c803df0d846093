// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces of remote measurement that need no network (issue #44): the event stream, base64, the ssh command
// line and what ssh's failures mean, the first-contact check's reading, the robots list, the SSH config's Hosts,
// and the robot's job agent run in-process (its cancel, its hang-up, nothing left running).
#include <QTemporaryDir>
#include <QTest>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <thread>

#include <fstream>
#include <iostream>
#include <sstream>

#include "../../support/run_on.h"
#include "remote/base64.h"
#include "remote/events.h"
#include "remote/job_agent.h"
#include "remote/process.h"
#include "remote/robot_check.h"
#include "remote/robots.h"
#include "remote/ssh.h"

using namespace bs::remote;

namespace {

std::vector<Event> events_of(const std::string& text) {
  std::vector<Event> list;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) list.push_back(parse_event(line));
  return list;
}

const Event* find(const std::vector<Event>& list, const std::string& type) {
  for (const Event& e : list)
    if (e.type == type) return &e;
  return nullptr;
}

// Running: the process exists and is not a zombie (a container's init may be slow to reap orphans).
bool alive(long long pid) {
  if (pid <= 0 || kill(static_cast<pid_t>(pid), 0) != 0) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const auto paren = text.rfind(')');
  return paren == std::string::npos || paren + 2 >= text.size() || text[paren + 2] != 'Z';
}

// What the agent sent for a job, event by event, and its exit status.
struct AgentRun {
  int status;
  std::vector<Event> events;
};

// Runs `job` in-process as the robot's agent; then closes both ends of the pipe its stdin came from (`in`), as the
// desk does when the job has ended.
AgentRun run_agent(const AgentJob& job, const int (&in)[2]) {
  std::ostringstream out, err;
  const int status = run_job_agent(job, out, err);
  ::close(in[1]);
  ::close(in[0]);
  return {status, events_of(out.str())};
}

nlohmann::json record_of(const QString& jobs, const std::string& id) {
  std::ifstream in(jobs.toStdString() + "/" + id + "/job.json");
  return nlohmann::json::parse(in, nullptr, false);
}

}  // namespace

class TestRemoteProtocol : public QObject {
  Q_OBJECT
 private slots:
  void events_round_trip() {
    std::ostringstream out;
    EventWriter w(out);
    w.progress(0.25, "W=64, D=4");
    w.write("power", {{"watts", {{"VDD_IN", 5.0}}}});
    w.end(0, false);
    const std::vector<Event> list = events_of(out.str());
    QCOMPARE(list.size(), std::size_t{3});
    QCOMPARE(list[0].type, std::string("progress"));
    QCOMPARE(list[0].body["v"].get<int>(), kEventsVersion);
    QCOMPARE(list[0].body["fraction"].get<double>(), 0.25);
    QCOMPARE(list[1].body["watts"]["VDD_IN"].get<double>(), 5.0);
    QCOMPARE(list[2].body["status"].get<int>(), 0);
    QVERIFY(list[2].body["t"].get<double>() >= list[0].body["t"].get<double>());
  }

  void events_refused_with_the_reason() {
    const auto reason = [](const std::string& line) {
      try {
        parse_event(line);
      } catch (const EventError& e) {
        return std::string(e.what());
      }
      return std::string("accepted");
    };
    QCOMPARE(reason("Welcome to the robot"), std::string("not JSON"));
    QCOMPARE(reason("[1,2]"), std::string("JSON but not an object"));
    QCOMPARE(reason(R"({"type":"progress"})"), std::string("no version field \"v\""));
    QVERIFY(reason(R"({"v":2,"type":"progress"})").find("version 2") != std::string::npos);
    QCOMPARE(reason(R"({"v":1})"), std::string("no event type \"type\""));
    QCOMPARE(reason(R"({"v":1,"type":"x"})"), std::string("accepted"));
    QVERIFY(reason(std::string(kMaxEventLineBytes + 1, ' ')).find("longer than") != std::string::npos);
  }

  void points_build_the_live_runs() {
    auto run = bs::test::run_on<bs::FlopsRun>("robot", "cpu", bs::DeviceKind::Cpu, "CPU scalar");
    run.variant = "throughput";
    run.iterations = 1000;
    run.dims = 2;
    std::vector<bs::FlopsRun> live;
    for (std::int64_t w : {4, 1, 2}) {
      run.samples = {{w, {0.5, 0.25}}};
      const Event e{"point", point_fields(run)};
      QCOMPARE(e.body["flops"].get<double>(), 6.0 * 2 * 1000 * static_cast<double>(w) / 0.375);
      apply_point(live, e);
    }
    QCOMPARE(live.size(), std::size_t{1});
    QCOMPARE(live[0].samples.size(), std::size_t{3});
    QCOMPARE(live[0].samples[0].workers, std::int64_t{1});  // ascending whatever the arrival order
    QCOMPARE(live[0].samples[2].workers, std::int64_t{4});
    QCOMPARE(live[0].backend, std::string("CPU scalar"));
    Event bad{"point", point_fields(run)};
    bad.body["seconds"] = nlohmann::json::array({0.0});
    QVERIFY_THROWS_EXCEPTION(EventError, apply_point(live, bad));
    bad.body["seconds"] = nlohmann::json::array({1.0});
    bad.body["workers"] = -3;
    QVERIFY_THROWS_EXCEPTION(EventError, apply_point(live, bad));
  }

  void base64_round_trip_and_refusals() {
    for (const std::string& s :
         std::vector<std::string>{"", "f", "fo", "foo", "foob", "fooba", "foobar", std::string("\0\xff\x10", 3)})
      QCOMPARE(*base64_decode(base64_encode(s)), s);
    QCOMPARE(base64_encode("foobar"), std::string("Zm9vYmFy"));
    QCOMPARE(base64_encode("fo"), std::string("Zm8="));
    QVERIFY(!base64_decode("Zm9"));       // length
    QVERIFY(!base64_decode("Zm=v"));      // padding inside
    QVERIFY(!base64_decode("Zm9v!A=="));  // alphabet
  }

  void lines_split_and_overlong_cut() {
    LineSplitter s(8);
    std::vector<std::pair<std::string, bool>> got;
    const auto on = [&](std::string_view l, bool over) { got.emplace_back(std::string(l), over); };
    s.feed("ab\ncd", on);
    s.feed("e\n0123456789ABC", on);
    s.feed("DEF\nz\n", on);
    QCOMPARE(got.size(), std::size_t{4});
    QCOMPARE(got[0].first, std::string("ab"));
    QCOMPARE(got[1].first, std::string("cde"));
    QCOMPARE(got[2].first, std::string("01234567"));
    QVERIFY(got[2].second);
    QCOMPARE(got[3].first, std::string("z"));  // the overlong line's rest is dropped, not a line of its own
  }

  void ssh_command_line() {
    QCOMPARE(shell_quote("run"), std::string("run"));
    QCOMPARE(shell_quote("1,2,4:64:4"), std::string("1,2,4:64:4"));
    QCOMPARE(shell_quote("a b"), std::string("'a b'"));
    QCOMPARE(shell_quote("it's"), std::string("'it'\\''s'"));
    QCOMPARE(shell_quote("$(reboot)"), std::string("'$(reboot)'"));
    QCOMPARE(shell_quote(""), std::string("''"));
    SshTarget t{"robot", "/tmp/cfg", "benchscope-cli"};
    const auto argv = ssh_argv(t, "echo hi");
    const auto has = [&](const std::string& w) { return std::find(argv.begin(), argv.end(), w) != argv.end(); };
    QVERIFY(has("BatchMode=yes") && has("-T") && has("/tmp/cfg"));
    QCOMPARE(argv[argv.size() - 3], std::string("--"));
    QCOMPARE(argv.back(), std::string("echo hi"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, check_destination("-oProxyCommand=touch /tmp/x"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, check_destination("robot 2"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, check_destination(""));
    check_destination("lab@10.0.0.7");
  }

  void ssh_failures_in_words() {
    const auto says = [](const char* err, const char* what) {
      const std::string m = describe_ssh_failure("jetson", err);
      return m.starts_with("jetson: ") && m.find(what) != std::string::npos;
    };
    QVERIFY(says("root@127.0.0.1: Permission denied (publickey).\n", "refused the login"));
    QVERIFY(says("root@127.0.0.1: Permission denied (publickey).\n", "ssh: root@127.0.0.1: Permission denied"));
    QVERIFY(
        says("No ED25519 host key is known for [127.0.0.1]:42022 and you have requested strict checking.\r\n"
             "Host key verification failed.\r\n",
             "host key is not known"));
    QVERIFY(says("@@@@\nWARNING: REMOTE HOST IDENTIFICATION HAS CHANGED!\n", "CHANGED"));
    QVERIFY(says("ssh: connect to host 127.0.0.1 port 42999: Connection refused\n", "cannot be reached"));
    QVERIFY(says("ssh: Could not resolve hostname nosuch: Name or service not known\n", "no such host"));
    QVERIFY(says("Connection to 127.0.0.1 closed by remote host.\n", "connection to the robot was lost"));
    QVERIFY(says("client_loop: send disconnect: Broken pipe\n", "lost"));
    QVERIFY(says("kex_exchange_identification: something new\n", "ssh failed"));
    QCOMPARE(last_ssh_line("Warning: Permanently added 'x' (ED25519) to the list of known hosts.\r\n"), std::string());
  }

  void versions_and_install_command() {
    QCOMPARE(compare_versions("0.1.0", "0.1.0"), 0);
    QCOMPARE(compare_versions("0.9.2", "0.10.0"), -1);
    QCOMPARE(compare_versions("1.0", "0.99.99"), 1);
    QCOMPARE(compare_versions("0.1", "0.1.0"), 0);
    QCOMPARE(debian_architecture("aarch64"), std::string("arm64"));
    QCOMPARE(debian_architecture("x86_64"), std::string("amd64"));
    QCOMPARE(install_command("jetson", "aarch64", "0.2.0"),
             std::string("scp benchscope-cli_0.2.0_arm64.deb jetson: && ssh -t jetson sudo apt install "
                         "./benchscope-cli_0.2.0_arm64.deb"));
  }

  void probe_read() {
    const std::string robot_event =
        R"j({"v":1,"type":"robot","host":"orin","arch":"aarch64","os":"Ubuntu 22.04","cpu":"ARMv8",)j"
        R"j("backends":[{"id":"cpu-simd","label":"CPU SIMD (NEON)","device":"12x Cortex-A78AE","kind":"cpu",)j"
        R"j("theoretical_peak_flops":1e11}],"sensors":[{"id":"ina3221:1-0040:VDD_IN","label":"VDD_IN",)j"
        R"j("kind":"ina3221","readable":true,"board_total":true}],"sensor_note":"the input rail","jobs_dir":"/j"})j";
    RemoteOutput ok{"Welcome!\nbenchscope-probe-v1\naarch64\norin\nbenchscope-cli 0.1.0\nbenchscope-probe-status 0\n" +
                        robot_event + "\n",
                    "", 0};
    RobotCheck c = read_probe("jetson", "0.1.0", ok, "benchscope-cli");
    QVERIFY2(c.ok, c.problem.c_str());
    QCOMPARE(c.info.arch, std::string("aarch64"));
    QCOMPARE(c.info.hostname, std::string("orin"));
    QCOMPARE(c.info.login_noise, std::vector<std::string>{"Welcome!"});
    QCOMPARE(c.info.backends.size(), std::size_t{1});
    QVERIFY(c.info.devices_text().find("CPU SIMD (NEON): 12x Cortex-A78AE") != std::string::npos);
    QVERIFY(c.info.devices_text().find("ina3221:1-0040:VDD_IN") != std::string::npos);

    c = read_probe("jetson", "0.2.0", ok, "benchscope-cli");  // the desk is newer
    QVERIFY(!c.ok);
    QVERIFY(c.problem.find("0.1.0, older than this desk's 0.2.0") != std::string::npos);
    QCOMPARE(c.fix, install_command("jetson", "aarch64", "0.2.0"));

    const RemoteOutput missing{"benchscope-probe-v1\naarch64\norin\nbenchscope-probe-missing\n", "", 0};
    c = read_probe("jetson", "0.1.0", missing, "benchscope-cli");
    QVERIFY(!c.ok && c.problem.find("not installed") != std::string::npos);
    QVERIFY(c.fix.find("benchscope-cli_0.1.0_arm64.deb") != std::string::npos);

    const RemoteOutput not_ours{"benchscope-probe-v1\nx86_64\nbox\nsomething else 3\nbenchscope-probe-status 0\n", "",
                                0};
    c = read_probe("box", "0.1.0", not_ours, "benchscope-cli");
    QVERIFY(!c.ok && c.problem.find("not BenchScope's CLI") != std::string::npos);

    const RemoteOutput refused{"", "root@box: Permission denied (publickey).\n", 255};
    c = read_probe("box", "0.1.0", refused, "benchscope-cli");
    QVERIFY(!c.ok && c.problem.find("refused the login") != std::string::npos);
  }

  void ssh_config_hosts_with_include() {
    QTemporaryDir dir;
    const std::string d = dir.path().toStdString();
    std::filesystem::create_directories(d + "/config.d");
    std::ofstream(d + "/config") << "# robots\nHost jetson orin-?\n  HostName 10.0.0.7\nHost *\n  User lab\n"
                                    "Include config.d/*.conf\nHost=pi5\n";
    std::ofstream(d + "/config.d/lab.conf") << "Host tx2 !bad\n";
    std::ofstream(d + "/config.d/skip.txt") << "Host notme\n";
    QCOMPARE(ssh_config_hosts(d + "/config"), (std::vector<std::string>{"jetson", "tx2", "pi5"}));
    QVERIFY(ssh_config_hosts(d + "/none").empty());
  }

  void robots_list_keeps_contacts_and_runs() {
    QTemporaryDir dir;
    const std::string file = dir.filePath("robots.json").toStdString();
    const std::string cfg = dir.filePath("ssh_config").toStdString();
    std::ofstream(cfg) << "Host jetson\n";
    {
      RobotList list(file);
      QCOMPARE(list.all(cfg).size(), std::size_t{1});
      QVERIFY(list.all(cfg)[0].from_ssh_config);
      Robot pi;
      pi.name = "lab@pi5";
      pi.added = true;
      pi.remote_cli = "/opt/bs/benchscope-cli";
      list.put(pi);
      RobotCheck c;
      c.ok = true;
      c.info.hostname = "orin";
      c.info.arch = "aarch64";
      c.info.cli_version = "0.1.0";
      list.record_check("jetson", c, SshTarget{"jetson", cfg, "benchscope-cli"});
      for (int i = 0; i < 60; ++i)
        list.record_run("jetson", {"2026-11-30T10:00:00Z", std::to_string(i), "run flops", "ok"});
    }
    RobotList again(file);
    const std::vector<Robot> all = again.all(cfg);
    QCOMPARE(all.size(), std::size_t{2});
    const Robot* j = again.find("jetson");
    QVERIFY(j && j->last_ok && j->hostname == "orin" && j->arch == "aarch64");
    QCOMPARE(j->runs.size(), kMaxRobotRuns);
    QCOMPARE(j->runs.back().job_id, std::string("59"));
    QCOMPARE(j->target().config_file, cfg);
    QCOMPARE(again.find("lab@pi5")->target().remote_cli, std::string("/opt/bs/benchscope-cli"));
    QVERIFY(again.remove("lab@pi5"));
    QVERIFY(!RobotList(file).find("lab@pi5"));
    std::ofstream(file) << "{\"robots\": 3}";
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, RobotList{file});
  }

  // The robots list words a job the same from the GUI and the CLI (#52): the whole command line, and an outcome
  // that says when the job ended early (its results are partial).
  void robots_list_words_a_job_once() {
    const RobotRun r = robot_run_started("j7", {"headroom", "--seconds", "2", "--load", "flops"});
    QCOMPARE(r.job_id, std::string("j7"));
    QCOMPARE(r.command, std::string("headroom --seconds 2 --load flops"));
    QCOMPARE(r.date.size(), std::string("2026-11-30T10:00:00Z").size());
    QVERIFY(r.outcome.empty());
    QCOMPARE(robot_run_outcome("done", "imported 1 run into a.bsw"), std::string("imported 1 run into a.bsw"));
    QCOMPARE(robot_run_outcome("cancelled", "imported 1 run into a.bsw"),
             std::string("cancelled, imported 1 run into a.bsw"));
    QCOMPARE(robot_run_outcome("interrupted", "nothing to import"), std::string("interrupted, nothing to import"));
    QCOMPARE(robot_run_outcome("failed", "failed: no such load"), std::string("failed: no such load"));
  }

  // The agent forwards the measurement's events, wraps stray text as messages, records the job and sends its
  // result files; fetch sends them again.
  void agent_runs_a_job() {
    QTemporaryDir dir;
    int in[2];
    QVERIFY(pipe(in) == 0);
    AgentJob job;
    job.id = "job-1";
    job.jobs_dir = dir.path().toStdString();
    job.command = {"run", "flops"};
    job.stdin_fd = in[0];
    job.body = [](const std::string& job_dir) {
      std::ofstream(job_dir + "/" + kJobResultFile) << std::string(100000, 'x');  // two chunks and a bit
      std::cout << R"({"v":1,"type":"progress","t":0,"fraction":0.5,"step":"half"})" << '\n'
                << "OpenCL build log: nothing to say\n"
                << R"({"v":1,"type":"end","t":0,"status":0,"cancelled":false})" << '\n'
                << std::flush;
      return 0;
    };
    const AgentRun run = run_agent(job, in);
    QCOMPARE(run.status, 0);
    const std::vector<Event>& list = run.events;
    QCOMPARE(list.front().type, std::string("job"));
    QCOMPARE(list.front().body["id"].get<std::string>(), std::string("job-1"));
    QVERIFY(find(list, "progress"));
    const Event* msg = find(list, "message");
    QVERIFY(msg && msg->body["text"].get<std::string>() == "OpenCL build log: nothing to say");
    std::string data;
    for (const Event& e : list)
      if (e.type == "file") data += *base64_decode(e.body["data"].get<std::string>());
    QCOMPARE(data, std::string(100000, 'x'));
    const Event& end = list.back();
    QCOMPARE(end.type, std::string("job_end"));
    QCOMPARE(end.body["status"].get<std::string>(), std::string("done"));
    QCOMPARE(end.body["files"][0]["name"].get<std::string>(), std::string(kJobResultFile));
    const nlohmann::json rec = record_of(dir.path(), "job-1");
    QCOMPARE(rec["status"].get<std::string>(), std::string("done"));
    QVERIFY(!alive(rec["child_pid"].get<long long>()));

    std::ostringstream again;
    QCOMPARE(fetch_job_agent(job.jobs_dir, "", again), 0);
    const std::vector<Event> fetched = events_of(again.str());
    QCOMPARE(fetched.back().type, std::string("job_end"));
    QVERIFY(fetched.back().body["files"] == end.body["files"]);
    std::ostringstream none;
    QCOMPARE(fetch_job_agent(job.jobs_dir, "nope", none), 1);
    QVERIFY(none.str().find("no job 'nope'") != std::string::npos);
    // The same id again is refused: a job folder is written once.
    std::ostringstream twice, err2;
    QCOMPARE(run_job_agent(job, twice, err2), 1);
    QVERIFY(twice.str().find("exists already") != std::string::npos);
  }

  // "cancel" on stdin: the measurement gets SIGINT (as Ctrl+C) and its completed part is sent.
  void agent_cancel_stops_the_measurement() {
    QTemporaryDir dir;
    int in[2];
    QVERIFY(pipe(in) == 0);
    QVERIFY(write(in[1], "cancel\n", 7) == 7);
    AgentJob job;
    job.id = "job-2";
    job.jobs_dir = dir.path().toStdString();
    job.command = {"run", "flops"};
    job.stdin_fd = in[0];
    job.body = [](const std::string&) {
      for (;;) pause();  // until a signal ends it: SIGINT's default action
      return 0;
    };
    const AgentRun run = run_agent(job, in);
    QCOMPARE(run.status, 0);
    const std::vector<Event>& list = run.events;
    QCOMPARE(list.back().body["status"].get<std::string>(), std::string("cancelled"));
    QCOMPARE(list.back().body["exit_status"].get<int>(), 128 + SIGINT);
    QVERIFY(find(list, "error"));  // it ended without its own end event: the agent says so
    const nlohmann::json rec = record_of(dir.path(), "job-2");
    QCOMPARE(rec["status"].get<std::string>(), std::string("cancelled"));
    QVERIFY(!alive(rec["child_pid"].get<long long>()));
  }

  // The end of stdin (the desk gone): the whole group is stopped, a child ignoring SIGTERM included, nothing is
  // sent, and the record says interrupted.
  void agent_hangup_leaves_nothing_running() {
    QTemporaryDir dir;
    int in[2];
    QVERIFY(pipe(in) == 0);
    // The desk goes away once the measurement has started its grandchild (the end of the agent's stdin). The
    // watcher only stats and sleeps (no allocation), as the agent forks while it runs.
    const std::string marker = dir.filePath("job-3/grandchild.pid").toStdString();
    std::thread desk([&marker, fd = in[1]] {
      struct stat st {};
      for (int i = 0; i < 3000 && stat(marker.c_str(), &st) != 0; ++i) usleep(10000);
      ::close(fd);
    });
    AgentJob job;
    job.id = "job-3";
    job.jobs_dir = dir.path().toStdString();
    job.command = {"record-power"};
    job.stdin_fd = in[0];
    job.body = [](const std::string& job_dir) {
      // A grandchild in the same group, as record-power's command would be; it ignores SIGTERM as a stubborn
      // program may, and holds the output pipe open.
      signal(SIGTERM, SIG_IGN);
      const pid_t grandchild = fork();
      if (grandchild == 0) {
        for (;;) pause();
      }
      std::ofstream(job_dir + "/grandchild.pid.tmp") << grandchild;
      std::rename((job_dir + "/grandchild.pid.tmp").c_str(), (job_dir + "/grandchild.pid").c_str());
      for (;;) pause();
      return 0;
    };
    std::ostringstream out, err;
    QCOMPARE(run_job_agent(job, out, err), 0);
    desk.join();
    ::close(in[0]);
    const std::vector<Event> list = events_of(out.str());
    QVERIFY(!find(list, "job_end"));
    QVERIFY(!find(list, "file"));
    const nlohmann::json rec = record_of(dir.path(), "job-3");
    QCOMPARE(rec["status"].get<std::string>(), std::string("interrupted"));
    QVERIFY(!alive(rec["child_pid"].get<long long>()));
    long long grandchild = 0;
    std::ifstream(dir.filePath("job-3/grandchild.pid").toStdString()) >> grandchild;
    QVERIFY(grandchild > 0);
    // The grandchild was killed with its group; it is reaped by init, so poll briefly until it is gone.
    for (int i = 0; i < 100 && alive(grandchild); ++i) QTest::qWait(20);
    QVERIFY(!alive(grandchild));
  }
};

QTEST_GUILESS_MAIN(TestRemoteProtocol)
#include "test_remote_protocol.moc"
