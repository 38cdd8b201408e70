#include "mbmodel/SampleTable.h"

#include "mbmodel/HugePageMemory.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>
#include <limits>
#include <stdexcept>
#include <utility>

namespace rockroll {

SampleTable::SampleTable(std::initializer_list<std::initializer_list<double>> rows) {
    if (rows.size() > 0) reserve(rows.size(), rows.begin()->size());
    for (const auto& r : rows) push_back(r);
}

SampleTable::SampleTable(const SampleTable& other) : width_(other.width_) {
    if (other.rows_ == 0) return;
    reserve(other.rows_, other.width_);
    std::memcpy(data_, other.data_, other.rows_ * other.width_ * sizeof(double));
    rows_ = other.rows_;
}

SampleTable::SampleTable(SampleTable&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      rows_(std::exchange(other.rows_, 0)),
      width_(std::exchange(other.width_, 0)),
      capacity_(std::exchange(other.capacity_, 0)) {}

SampleTable& SampleTable::operator=(const SampleTable& other) {
    if (this != &other) *this = SampleTable(other);
    return *this;
}

SampleTable& SampleTable::operator=(SampleTable&& other) noexcept {
    if (this != &other) {
        std::free(data_);
        data_ = std::exchange(other.data_, nullptr);
        rows_ = std::exchange(other.rows_, 0);
        width_ = std::exchange(other.width_, 0);
        capacity_ = std::exchange(other.capacity_, 0);
    }
    return *this;
}

SampleTable::~SampleTable() { std::free(data_); }

void SampleTable::checkRows(std::size_t rows, std::size_t width) const {
    if (width == 0) throw std::invalid_argument("SampleTable: a row holds at least one value");
    if (width_ != 0 && width != width_)
        throw std::invalid_argument(fmt::format("SampleTable: rows of {} values given; the table's hold {}", width,
                                                width_));
    if (rows > std::numeric_limits<std::size_t>::max() / sizeof(double) / width)
        throw std::length_error(fmt::format("SampleTable: {} rows of {} values cannot be addressed", rows, width));
}

void SampleTable::reserve(std::size_t rows, std::size_t width) {
    checkRows(rows, width);
    if (rows * width > capacity_) std::free(moveTo(rows * width));
    width_ = width;
}

double* SampleTable::moveTo(std::size_t values) {
    const std::size_t bytes = values * sizeof(double);
    double* fresh = static_cast<double*>(allocateLargeBuffer(bytes));
    if (rows_ > 0) std::memcpy(fresh, data_, rows_ * width_ * sizeof(double));
    capacity_ = getLargeBufferCapacity(bytes) / sizeof(double);
    return std::exchange(data_, fresh);
}

double* SampleTable::grow(std::size_t width, double*& old) {
    const std::size_t rows = std::max<std::size_t>(64, 2 * rows_);  // room for rows_ + 1, doubling
    checkRows(rows, width);
    if ((rows_ + 1) * width > capacity_) old = moveTo(rows * width);
    width_ = width;
    return data_ + rows_ * width_;
}

SampleTable::Row SampleTable::push_back(Row row) {
    double* old = nullptr;  // `row` may lie there: freed after the copy
    double* at = grow(row.size(), old);
    std::copy(row.begin(), row.end(), at);
    std::free(old);
    ++rows_;
    return back();
}

SampleTable::Row SampleTable::append(double t, Row values) {
    double* old = nullptr;  // `values` may lie there: freed after the copy
    double* at = grow(1 + values.size(), old);
    at[0] = t;
    std::copy(values.begin(), values.end(), at + 1);
    std::free(old);
    ++rows_;
    return back();
}

void SampleTable::set(std::size_t i, Row row) {
    if (i >= rows_ || row.size() != width_)
        throw std::invalid_argument(fmt::format("SampleTable::set: row {} of {} values; the table has {} rows of {}", i,
                                                row.size(), rows_, width_));
    std::memmove(data_ + i * width_, row.data(), width_ * sizeof(double));  // row may be a row of the table
}

bool operator==(const SampleTable& a, const SampleTable& b) {
    if (a.rows_ != b.rows_ || (a.rows_ > 0 && a.width_ != b.width_)) return false;
    return std::equal(a.data_, a.data_ + a.rows_ * a.width_, b.data_);
}

}  // namespace rockroll
