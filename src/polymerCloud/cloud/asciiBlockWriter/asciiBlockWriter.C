/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

\*---------------------------------------------------------------------------*/

#include "asciiBlockWriter.H"
#include "token.H"

#include <charconv>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Longest number: a sign, 17 digits and a point, an exponent of 5
constexpr size_t longestNumber = 32;

// A block's size: written when the next item might not fit
constexpr size_t blockSize = 1 << 16;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::asciiBlockWriter::asciiBlockWriter(Ostream& os)
:
    os_(os),
    precision_(os.precision()),
    block_(blockSize),
    used_(0)
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::polymer::asciiBlockWriter::~asciiBlockWriter()
{
    flush();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::asciiBlockWriter::reserve(const size_t n)
{
    if (used_ + n > block_.size())
    {
        flush();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::asciiBlockWriter::flush()
{
    if (used_)
    {
        os_.writeRaw(block_.data(), used_);
        used_ = 0;
    }
}


// * * * * * * * * * * * * * * * Member Operators  * * * * * * * * * * * * * //

Foam::polymer::asciiBlockWriter&
Foam::polymer::asciiBlockWriter::operator<<(const char c)
{
    reserve(1);
    block_[used_++] = c;
    return *this;
}


Foam::polymer::asciiBlockWriter&
Foam::polymer::asciiBlockWriter::operator<<(const label i)
{
    reserve(longestNumber);
    char* const first = block_.data() + used_;
    used_ = std::to_chars(first, first + longestNumber, i).ptr - block_.data();
    return *this;
}


Foam::polymer::asciiBlockWriter&
Foam::polymer::asciiBlockWriter::operator<<(const scalar x)
{
    // As printf's %.*g at the stream's precision: what std::ostream's
    // operator<< writes with no floatfield set, as OSstream leaves it
    reserve(longestNumber);
    char* const first = block_.data() + used_;
    used_ =
        std::to_chars
        (
            first, first + longestNumber, x, std::chars_format::general,
            precision_
        ).ptr
      - block_.data();
    return *this;
}


Foam::polymer::asciiBlockWriter&
Foam::polymer::asciiBlockWriter::operator<<(const vector& v)
{
    return
        *this
        << char(token::BEGIN_LIST) << v.x() << char(token::SPACE) << v.y()
        << char(token::SPACE) << v.z() << char(token::END_LIST);
}


// ************************************************************************* //
