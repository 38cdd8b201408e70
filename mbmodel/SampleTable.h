#pragma once
// A run's recorded samples: rows of one width (time, then the channels) in one block.
// No Simbody dependency.
//
// One buffer instead of a heap allocation per row: a model that knows how many samples it
// will record reserves them once, and a buffer of kLargeBufferBytes or more lives in huge
// pages (mbmodel/HugePageMemory.h), so recording does not pay a page fault every 4 KB.
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <span>
#include <vector>

namespace rockroll {

class SampleTable {
public:
    using Row = std::span<const double>;

    class const_iterator {
    public:
        // A row is a span made on the fly (as std::views::transform's iterators): random
        // access for C++20's concepts, input for the older iterator rules.
        using iterator_concept = std::random_access_iterator_tag;
        using iterator_category = std::input_iterator_tag;
        using value_type = Row;
        using difference_type = std::ptrdiff_t;
        using reference = Row;
        using pointer = void;
        const_iterator() = default;
        Row operator*() const { return {p_, width_}; }
        Row operator[](difference_type n) const { return *(*this + n); }
        const_iterator& operator++() { return p_ += width_, *this; }
        const_iterator operator++(int) { const_iterator c = *this; return ++*this, c; }
        const_iterator& operator--() { return p_ -= width_, *this; }
        const_iterator operator--(int) { const_iterator c = *this; return --*this, c; }
        const_iterator& operator+=(difference_type n) { return p_ += n * difference_type(width_), *this; }
        const_iterator& operator-=(difference_type n) { return *this += -n; }
        friend const_iterator operator+(const_iterator a, difference_type n) { return a += n; }
        friend const_iterator operator+(difference_type n, const_iterator a) { return a += n; }
        friend const_iterator operator-(const_iterator a, difference_type n) { return a -= n; }
        friend difference_type operator-(const const_iterator& a, const const_iterator& b) {
            return a.width_ == 0 ? 0 : (a.p_ - b.p_) / difference_type(a.width_);
        }
        friend bool operator==(const const_iterator& a, const const_iterator& b) { return a.p_ == b.p_; }
        friend auto operator<=>(const const_iterator& a, const const_iterator& b) { return a.p_ <=> b.p_; }

    private:
        friend class SampleTable;
        const_iterator(const double* p, std::size_t width) : p_(p), width_(width) {}
        const double* p_ = nullptr;
        std::size_t width_ = 0;
    };

    SampleTable() = default;
    /// Rows given whole, all of one width (tests, small tables).
    SampleTable(std::initializer_list<std::initializer_list<double>> rows);
    SampleTable(const SampleTable& other);
    SampleTable(SampleTable&& other) noexcept;
    SampleTable& operator=(const SampleTable& other);
    SampleTable& operator=(SampleTable&& other) noexcept;
    ~SampleTable();

    std::size_t size() const { return rows_; }
    bool empty() const { return rows_ == 0; }
    /// Values per row; 0 before the first row or reserve.
    std::size_t getWidth() const { return width_; }
    Row operator[](std::size_t i) const { return {data_ + i * width_, width_}; }
    /// The rows one after another, size() × getWidth() values.
    const double* data() const { return data_; }
    Row front() const { return (*this)[0]; }
    Row back() const { return (*this)[rows_ - 1]; }
    const_iterator begin() const { return {data_, width_}; }
    const_iterator end() const { return {data_ + rows_ * width_, width_}; }

    /// Room for `rows` rows of `width` values (the width the rows must then have).
    /// Throws std::length_error when that many values cannot be addressed.
    void reserve(std::size_t rows, std::size_t width);
    /// Appends a row (it may be a row of the table); the first row sets the width, and a
    /// row of another width throws std::invalid_argument. Returns the stored row (valid
    /// until the next append).
    Row push_back(Row row);
    Row push_back(std::initializer_list<double> row) { return push_back(Row(row.begin(), row.size())); }
    /// Appends t followed by `values` (one row of 1 + values.size()).
    Row append(double t, Row values);
    /// Overwrites row i with `row` (of the table's width; it may be a row of the table).
    void set(std::size_t i, Row row);
    void set(std::size_t i, std::initializer_list<double> row) { set(i, Row(row.begin(), row.size())); }

    friend bool operator==(const SampleTable& a, const SampleTable& b);

private:
    /// Throws unless `rows` rows of `width` values fit this table and can be addressed.
    void checkRows(std::size_t rows, std::size_t width) const;
    /// Moves the rows to a buffer of `values` values; returns the old buffer, which the
    /// caller frees once it has read what it needs from it (a row appended from the table).
    [[nodiscard]] double* moveTo(std::size_t values);
    /// Where the next row of `width` values goes; `old` receives a buffer to free after the copy.
    double* grow(std::size_t width, double*& old);
    double* data_ = nullptr;
    std::size_t rows_ = 0, width_ = 0, capacity_ = 0;  // capacity_ in values
};

/// A row as a vector of its own.
inline std::vector<double> toVector(SampleTable::Row row) { return {row.begin(), row.end()}; }

}  // namespace rockroll
