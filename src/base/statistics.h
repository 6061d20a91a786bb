#pragma once
// Statistics declared once, as gem5's statistics::Group and ADD_STAT or pbrt-v4's STAT_COUNTER
// declare theirs: a plain struct of values declares each of its statistics beside it, with its
// key (as in the JSON; '/' nests objects), unit, one line of documentation and how it combines
// over the parts of a run (cores, frames, sampled blocks, rows) and over windows (a run less a
// prefix of it). From the declarations come the sums and window differences here, and the JSON,
// CSV columns, report lines and `rtusim stats --list` (run/statistics_output.h).
//
// A struct S declares its statistics in `static const StatisticGroup<S>& declaration();`:
//   count      a counter (uint64_t): parts add up; a window is the whole less the prefix
//   maximum    the largest part (uint64_t); a window keeps the whole run's, as a part has no
//              maximum of its own to subtract
//   real       a real-valued sum (double): host seconds
//   histogram  value -> how often: bins add up (and subtract)
//   setting    what the run was (configuration, the model that answered): not combined, the
//              first part's
//   derived    computed from the others when written: ratios, shares, rates
//   group      a member struct (or an optional one) with its own declaration, at its key (an
//              empty key: its statistics among the holder's)
//   base       a base class with its own declaration, its statistics among the holder's
//   combinedBase  a base class combined with the holder but written by another entry
//   computed   a struct of another declaration computed for writing (the L1s summed)
//   list       one struct per part (per core) as an array; its statistics marked runTotal() are
//              written once beside the array, summed over the parts (a kind's counters of rays)
// and writtenWhen(...) after any of them writes it only when the values say so. A group is
// combined statistic by statistic; writers (StatisticWriter) see the values in declaration
// order, which is the order of the JSON.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace rtu {

using Histogram = std::map<uint64_t, uint64_t>;  // value -> how often

enum class Combine { Sum, Max, Setting, Derived };
// Whether a statistic of a list's parts is written in each part or once for the run, summed.
enum class Scope { EachPart, RunTotal };
// A histogram written as an array indexed by value, or as an object keyed by the value's text.
enum class HistogramForm { Array, Object };

struct Statistic {
  std::string key;   // "port_queue_cycles", or a path below its group: "memory/kind"
  std::string unit;  // "cycles", "rays", "bytes", "MHz", ...; empty for shares and text
  std::string doc;
  Combine combine = Combine::Sum;  // set by the group's declaring function
  Scope scope = Scope::EachPart;
  HistogramForm form = HistogramForm::Array;
  bool reported = false;  // the run's report has a line for it when it is not 0
  std::string note;       // said in parentheses on that line
  bool column = true;     // false: carried with the values (worker lines), not a CSV column

  Statistic(std::string key, std::string unit, std::string doc)
      : key(std::move(key)), unit(std::move(unit)), doc(std::move(doc)) {}
  // Written once for the run, summed over the parts of the list that holds it.
  Statistic runTotal() const {
    return with([](Statistic& s) { s.scope = Scope::RunTotal; });
  }
  // A line in the run's report when not 0: "<key, '_' as spaces>: <value> <unit> (<note>)".
  Statistic reportedWhenNotZero(std::string note = "") const {
    return with([&note](Statistic& s) { s.reported = true, s.note = std::move(note); });
  }
  Statistic keyedByValue() const {
    return with([](Statistic& s) { s.form = HistogramForm::Object; });
  }
  // What derived values need (a clock), carried with the values but not a column of their CSV.
  Statistic notAColumn() const {
    return with([](Statistic& s) { s.column = false; });
  }

 private:
  template <class F>
  Statistic with(F change) const {
    Statistic copy = *this;
    change(copy);
    return copy;
  }
};

// One value as writers see it and readers give it back; a vector of reals is an interval.
using StatisticValue =
    std::variant<uint64_t, int64_t, double, std::string, Histogram, std::vector<double>>;

// Receives a group's values in declaration order. Keys are relative to the groups entered.
class StatisticWriter {
 public:
  virtual ~StatisticWriter() = default;
  virtual void value(const Statistic& statistic, const StatisticValue& value) = 0;
  virtual void enter(const Statistic& group) = 0;     // an object at group.key, until leave()
  virtual void enterList(const Statistic& list) = 0;  // an array at list.key: parts, then leave()
  virtual void enterPart(size_t index) = 0;           // one part of the list, until leave()
  virtual void leave() = 0;
};

// Gives stored values back by key (a worker's line); a missing key leaves the value as it is.
class StatisticReader {
 public:
  virtual ~StatisticReader() = default;
  virtual std::optional<StatisticValue> value(const Statistic& statistic) = 0;
  virtual bool enter(const Statistic& group) = 0;  // false: no such group, nothing to read
  virtual void leave() = 0;
};

// What a list's parts are written with: the whole, the part's index and its values.
template <class Whole, class Part>
struct PartOf {
  const Whole& whole;
  size_t index;
  const Part& values;
};

template <class V>
class StatisticGroup {
 public:
  using When = std::function<bool(const V&)>;  // whether a statistic is written; empty: always

  // `title` heads the group in `rtusim stats --list`.
  explicit StatisticGroup(std::string title) : title_(std::move(title)) {}
  const std::string& title() const { return title_; }

  StatisticGroup& count(Statistic s, uint64_t V::*member) {
    return stored(
        s, Combine::Sum, member, [](uint64_t& a, uint64_t b) { a += b; },
        [](uint64_t& a, uint64_t b) { a -= std::min(a, b); });
  }
  StatisticGroup& maximum(Statistic s, uint64_t V::*member) {
    return stored(
        s, Combine::Max, member, [](uint64_t& a, uint64_t b) { a = std::max(a, b); },
        [](uint64_t&, uint64_t) {});
  }
  StatisticGroup& real(Statistic s, double V::*member) {
    return stored(
        s, Combine::Sum, member, [](double& a, double b) { a += b; },
        [](double& a, double b) { a -= b; });
  }
  StatisticGroup& histogram(Statistic s, Histogram V::*member) {
    const auto combine = [](Histogram& a, const Histogram& b, bool add) {
      for (const auto& [value, times] : b) {
        uint64_t& bin = a[value];
        bin = add ? bin + times : bin - std::min(bin, times);
        if (bin == 0) a.erase(value);
      }
    };
    return stored(
        s, Combine::Sum, member,
        [combine](Histogram& a, const Histogram& b) { combine(a, b, true); },
        [combine](Histogram& a, const Histogram& b) { combine(a, b, false); });
  }
  // A stored member (int, uint64_t, double or std::string) that is not combined.
  template <class M>
  StatisticGroup& setting(Statistic s, M V::*member) {
    return stored(s, Combine::Setting, member, nullptr, nullptr);
  }
  // A setting computed from the values (the memory's kind from a flag).
  template <class F>
  StatisticGroup& setting(Statistic s, F f) {
    return computedValue(s, Combine::Setting, f);
  }
  // `f(values)` (a function, or a member function or data member of V) gives a number, text, a
  // histogram, an interval or a StatisticValue.
  template <class F>
  StatisticGroup& derived(Statistic s, F f) {
    return computedValue(s, Combine::Derived, f);
  }
  // The statistic (or group) declared last is written only when `when(values)` holds.
  StatisticGroup& writtenWhen(When when) {
    entries_.back().when = std::move(when);
    return *this;
  }

  template <class G>
  StatisticGroup& group(Statistic s, G V::*member) {
    Entry entry =
        groupEntry<G>(s, [member](const V& values) -> const G* { return &(values.*member); });
    entry.add = [member](V& a, const V& b) { G::declaration().add(a.*member, b.*member); };
    entry.subtract = [member](V& a, const V& b) {
      G::declaration().subtract(a.*member, b.*member);
    };
    entry.read = [s, member](V& values, StatisticReader& reader) {
      if (s.key.empty()) return G::declaration().read(values.*member, reader);
      if (!reader.enter(s)) return;
      G::declaration().read(values.*member, reader);
      reader.leave();
    };
    entries_.push_back(std::move(entry));
    return *this;
  }
  // Written when present; a part that has it starts the sum, and both must have it to subtract.
  template <class G>
  StatisticGroup& group(Statistic s, std::optional<G> V::*member) {
    Entry entry = groupEntry<G>(s, [member](const V& values) -> const G* {
      return (values.*member) ? &*(values.*member) : nullptr;
    });
    entry.add = [member](V& a, const V& b) {
      if (!(b.*member)) return;
      if (a.*member)
        G::declaration().add(*(a.*member), *(b.*member));
      else
        a.*member = b.*member;
    };
    entry.subtract = [member](V& a, const V& b) {
      if (a.*member && b.*member) G::declaration().subtract(*(a.*member), *(b.*member));
    };
    entries_.push_back(std::move(entry));
    return *this;
  }
  // The statistics of V's base class B among V's own, at this place (a core's statistics hold
  // its kind's counters so).
  template <class B>
  StatisticGroup& base() {
    static_assert(std::is_base_of_v<B, V>, "base() declares a base class of the values");
    Entry entry =
        groupEntry<B>(Statistic("", "", ""), [](const V& values) -> const B* { return &values; });
    entry.add = [](V& a, const V& b) { B::declaration().add(a, b); };
    entry.subtract = [](V& a, const V& b) { B::declaration().subtract(a, b); };
    entry.read = [](V& values, StatisticReader& reader) { B::declaration().read(values, reader); };
    entries_.push_back(std::move(entry));
    return *this;
  }
  // The statistics of V's base class B combined (summed, subtracted, read back) with V's but
  // written by another entry: a core's kind counters, which the run writes for its own kind only.
  template <class B>
  StatisticGroup& combinedBase() {
    static_assert(std::is_base_of_v<B, V>, "combinedBase() declares a base class of the values");
    Entry entry{Statistic("", "", ""), Kind::Group};
    entry.add = [](V& a, const V& b) { B::declaration().add(a, b); };
    entry.subtract = [](V& a, const V& b) { B::declaration().subtract(a, b); };
    entry.read = [](V& values, StatisticReader& reader) { B::declaration().read(values, reader); };
    entries_.push_back(std::move(entry));
    return *this;
  }
  // The entries `declare(group)` adds, at this place (a fold over a list of types).
  template <class F>
  StatisticGroup& extend(F declare) {
    declare(*this);
    return *this;
  }
  // A struct of G's declaration computed from the values for writing (the L1s summed); it is not
  // combined itself, its sources are.
  template <class G, class F>
  StatisticGroup& computed(Statistic s, F f) {
    Entry entry = groupEntry<G>(s, nullptr);
    entry.write = [s, f](const V& values, StatisticWriter& writer, std::optional<Scope> scope) {
      writeGroup(s, G::declaration(), std::invoke(f, values), writer, scope);
    };
    entries_.push_back(std::move(entry));
    return *this;
  }
  // One G per part, combined index by index (as far as both go). Each part is written with
  // `layout` (whose own() writes G's statistics), or with G's statistics alone; G's runTotal()
  // statistics follow the array, summed over the parts.
  template <class G>
  StatisticGroup& list(Statistic s, std::vector<G> V::*member,
                       const StatisticGroup<PartOf<V, G>>* layout = nullptr) {
    combinedOnly(member);
    Entry& entry = entries_.back();
    entry.statistic = s;
    entry.kind = Kind::List;
    entry.write = [s, member, layout](const V& values, StatisticWriter& writer,
                                      std::optional<Scope> scope) {
      if (scope == Scope::RunTotal) return;
      const std::vector<G>& parts = values.*member;
      writer.enterList(s);
      for (size_t i = 0; i < parts.size(); ++i) {
        writer.enterPart(i);
        if (layout)
          layout->write(PartOf<V, G>{values, i, parts[i]}, writer, Scope::EachPart);
        else
          G::declaration().write(parts[i], writer, Scope::EachPart);
        writer.leave();
      }
      writer.leave();
      G::declaration().write(G::declaration().sum(parts), writer, Scope::RunTotal);
    };
    entry.describe = [s, layout](std::vector<Statistic>& out, const std::string& prefix,
                                 std::optional<Scope> scope) {
      if (scope == Scope::RunTotal) return;
      if (layout)
        layout->describe(out, prefix + s.key + "/*/", Scope::EachPart);
      else
        G::declaration().describe(out, prefix + s.key + "/*/", Scope::EachPart);
      G::declaration().describe(out, prefix, Scope::RunTotal);
    };
    return *this;
  }
  // One G per part, combined index by index and written by other entries (each core's L1 in the
  // cores' layout, their sum computed).
  template <class G>
  StatisticGroup& combinedOnly(std::vector<G> V::*member) {
    Entry entry{Statistic("", "", ""), Kind::List};
    entry.add = [member](V& a, const V& b) { G::declaration().addEach(a.*member, b.*member); };
    entry.subtract = [member](V& a, const V& b) {
      G::declaration().subtractEach(a.*member, b.*member);
    };
    entries_.push_back(std::move(entry));
    return *this;
  }
  // In a list's layout (V = PartOf<Whole, G>): the part's own statistics, at this place.
  template <class Whole, class G>
  StatisticGroup& own() {
    static_assert(std::is_same_v<V, PartOf<Whole, G>>, "own() belongs in a list's layout");
    Entry entry = groupEntry<G>(Statistic("", "", ""), [](const V& part) { return &part.values; });
    entries_.push_back(std::move(entry));
    return *this;
  }

  // total += part: sums, maxima, histograms, groups and lists.
  void add(V& total, const V& part) const {
    for (const Entry& entry : entries_)
      if (entry.add) entry.add(total, part);
  }
  // whole -= prefix: what the run counted after the prefix; maxima stay the whole's.
  void subtract(V& whole, const V& prefix) const {
    for (const Entry& entry : entries_)
      if (entry.subtract) entry.subtract(whole, prefix);
  }
  // The parts summed, with the first part's settings; no parts sum to V{}.
  V sum(const std::vector<V>& parts) const {
    if (parts.empty()) return V{};
    V total = parts.front();
    for (size_t i = 1; i < parts.size(); ++i) add(total, parts[i]);
    return total;
  }
  void addEach(std::vector<V>& totals, const std::vector<V>& parts) const {
    for (size_t i = 0; i < totals.size() && i < parts.size(); ++i) add(totals[i], parts[i]);
  }
  void subtractEach(std::vector<V>& wholes, const std::vector<V>& prefixes) const {
    for (size_t i = 0; i < wholes.size() && i < prefixes.size(); ++i)
      subtract(wholes[i], prefixes[i]);
  }

  // The values in declaration order; `scope`: only a list part's statistics, or its run totals.
  void write(const V& values, StatisticWriter& writer, std::optional<Scope> scope = {}) const {
    for (const Entry& entry : entries_) {
      if (!entry.write || !inScope(entry, scope) || (entry.when && !entry.when(values))) continue;
      entry.write(values, writer, scope);
    }
  }
  // Stored values back from a reader: settings, counters, maxima, reals, histograms and groups.
  void read(V& values, StatisticReader& reader) const {
    for (const Entry& entry : entries_)
      if (entry.read) entry.read(values, reader);
  }
  // Every statistic that may be written, keys as full paths below `prefix` ("cores/*/jobs").
  void describe(std::vector<Statistic>& out, const std::string& prefix = "",
                std::optional<Scope> scope = {}) const {
    for (const Entry& entry : entries_) {
      if (!entry.write || !inScope(entry, scope)) continue;
      if (entry.describe) {
        entry.describe(out, prefix, scope);
        continue;
      }
      Statistic full = entry.statistic;
      full.key = prefix + full.key;
      out.push_back(full);
    }
  }
  std::vector<Statistic> statistics(std::optional<Scope> scope = {}) const {
    std::vector<Statistic> all;
    describe(all, "", scope);
    return all;
  }

 private:
  enum class Kind { Value, Group, List };
  struct Entry {
    explicit Entry(Statistic s, Kind k = Kind::Value) : statistic(std::move(s)), kind(k) {}
    Statistic statistic;
    Kind kind;
    // Each empty where it does not apply: not combined, not written, not read back.
    std::function<void(V&, const V&)> add, subtract;
    std::function<void(const V&, StatisticWriter&, std::optional<Scope>)> write;
    std::function<void(V&, StatisticReader&)> read;
    When when;
    // Groups and lists: their statistics as full paths below the prefix.
    std::function<void(std::vector<Statistic>&, const std::string&, std::optional<Scope>)> describe;
  };

  // A value is written in the scope it is declared for; groups and lists pass the scope on.
  static bool inScope(const Entry& entry, std::optional<Scope> scope) {
    return !scope || entry.kind != Kind::Value || entry.statistic.scope == *scope;
  }

  // A group's statistics at s.key (an empty key: among the values of the group holding it).
  template <class G>
  static void writeGroup(const Statistic& s, const StatisticGroup<G>& declaration, const G& values,
                         StatisticWriter& writer, std::optional<Scope> scope) {
    if (scope && declaration.statistics(scope).empty()) return;
    if (!s.key.empty()) writer.enter(s);
    declaration.write(values, writer, scope);
    if (!s.key.empty()) writer.leave();
  }
  template <class G, class Get>
  Entry groupEntry(const Statistic& s, Get get) {
    Entry entry{s, Kind::Group};
    if constexpr (!std::is_same_v<Get, std::nullptr_t>) {
      entry.write = [s, get](const V& values, StatisticWriter& writer, std::optional<Scope> scope) {
        if (const G* group = get(values)) writeGroup(s, G::declaration(), *group, writer, scope);
      };
    }
    entry.describe = [s](std::vector<Statistic>& out, const std::string& prefix,
                         std::optional<Scope> scope) {
      G::declaration().describe(out, s.key.empty() ? prefix : prefix + s.key + "/", scope);
    };
    return entry;
  }
  template <class F>
  StatisticGroup& computedValue(Statistic s, Combine combine, F f) {
    s.combine = combine;
    Entry entry{s};
    entry.write = [s, f](const V& values, StatisticWriter& writer, std::optional<Scope>) {
      writer.value(s, valueOf(std::invoke(f, values)));
    };
    entries_.push_back(std::move(entry));
    return *this;
  }
  template <class M, class Add, class Subtract>
  StatisticGroup& stored(Statistic s, Combine combine, M V::*member, Add add, Subtract subtract) {
    s.combine = combine;
    Entry entry{s};
    if constexpr (!std::is_same_v<Add, std::nullptr_t>) {
      entry.add = [member, add](V& a, const V& b) { add(a.*member, b.*member); };
      entry.subtract = [member, subtract](V& a, const V& b) { subtract(a.*member, b.*member); };
    }
    entry.write = [s, member](const V& values, StatisticWriter& writer, std::optional<Scope>) {
      writer.value(s, valueOf(values.*member));
    };
    entry.read = [s, member](V& values, StatisticReader& reader) {
      if (const std::optional<StatisticValue> value = reader.value(s))
        assign(values.*member, *value);
    };
    entries_.push_back(std::move(entry));
    return *this;
  }

  template <class T>
  static StatisticValue valueOf(const T& value) {
    if constexpr (std::is_same_v<T, StatisticValue> || std::is_same_v<T, Histogram> ||
                  std::is_same_v<T, double> || std::is_same_v<T, std::string> ||
                  std::is_same_v<T, std::vector<double>>)
      return value;
    else if constexpr (std::is_convertible_v<T, std::string>)
      return std::string(value);
    else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>)
      return static_cast<int64_t>(value);
    else
      return static_cast<uint64_t>(value);
  }
  template <class M>
  static void assign(M& member, const StatisticValue& value) {
    std::visit(
        [&member](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, M>)
            member = v;
          else if constexpr (std::is_arithmetic_v<T> && std::is_arithmetic_v<M>)
            member = static_cast<M>(v);
        },
        value);
  }

  std::string title_;
  std::vector<Entry> entries_;
};

// The declared combinations of any struct S with S::declaration().
template <class S>
void addStatisticsOf(S& total, const S& part) {
  S::declaration().add(total, part);
}
template <class S>
void subtractStatisticsOf(S& whole, const S& prefix) {
  S::declaration().subtract(whole, prefix);
}
template <class S>
S sumOf(const std::vector<S>& parts) {
  return S::declaration().sum(parts);
}

}  // namespace rtu
