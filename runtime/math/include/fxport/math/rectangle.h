// Point and Rectangle: XNA's integer 2D types (pixels: +Y goes down the screen, so Top < Bottom).
#pragma once

namespace fxport {

struct Point {
    int X = 0;
    int Y = 0;

    constexpr Point() = default;
    constexpr Point(int x, int y) : X(x), Y(y) {}

    static const Point Zero;

    friend constexpr bool operator==(const Point&, const Point&) = default;
};

inline constexpr Point Point::Zero{0, 0};

struct Rectangle {
    int X = 0;
    int Y = 0;
    int Width = 0;
    int Height = 0;

    constexpr Rectangle() = default;
    constexpr Rectangle(int x, int y, int width, int height)
        : X(x), Y(y), Width(width), Height(height) {}

    static const Rectangle Empty;

    constexpr int Left() const { return X; }
    constexpr int Right() const { return X + Width; }
    constexpr int Top() const { return Y; }
    constexpr int Bottom() const { return Y + Height; }
    constexpr Point Location() const { return {X, Y}; }
    constexpr void setLocation(Point p) { X = p.X; Y = p.Y; }
    // Integer division, as XNA: the centre of a 3-wide rectangle at 0 is 1.
    constexpr Point Center() const { return {X + Width / 2, Y + Height / 2}; }
    constexpr bool IsEmpty() const { return Width == 0 && Height == 0 && X == 0 && Y == 0; }

    // Half-open: the left and top edges are inside, the right and bottom edges are not.
    constexpr bool Contains(int x, int y) const {
        return X <= x && x < X + Width && Y <= y && y < Y + Height;
    }
    constexpr bool Contains(Point p) const { return Contains(p.X, p.Y); }
    constexpr bool Contains(const Rectangle& r) const {
        return X <= r.X && r.X + r.Width <= X + Width && Y <= r.Y && r.Y + r.Height <= Y + Height;
    }
    // True when the interiors overlap; rectangles that only share an edge do not intersect.
    constexpr bool Intersects(const Rectangle& r) const {
        return r.X < X + Width && X < r.X + r.Width && r.Y < Y + Height && Y < r.Y + r.Height;
    }

    constexpr void Offset(int offsetX, int offsetY) { X += offsetX; Y += offsetY; }
    constexpr void Offset(Point amount) { Offset(amount.X, amount.Y); }
    // Grows by the amounts on every side (so the size grows by twice each amount).
    constexpr void Inflate(int horizontalAmount, int verticalAmount) {
        X -= horizontalAmount;
        Y -= verticalAmount;
        Width += horizontalAmount * 2;
        Height += verticalAmount * 2;
    }

    // The overlap, or Empty when there is none.
    static constexpr Rectangle Intersect(const Rectangle& a, const Rectangle& b) {
        const int left = a.X > b.X ? a.X : b.X;
        const int top = a.Y > b.Y ? a.Y : b.Y;
        const int right = a.Right() < b.Right() ? a.Right() : b.Right();
        const int bottom = a.Bottom() < b.Bottom() ? a.Bottom() : b.Bottom();
        if (right > left && bottom > top) {
            return {left, top, right - left, bottom - top};
        }
        return {};
    }
    // The smallest rectangle containing both.
    static constexpr Rectangle Union(const Rectangle& a, const Rectangle& b) {
        const int left = a.X < b.X ? a.X : b.X;
        const int top = a.Y < b.Y ? a.Y : b.Y;
        const int right = a.Right() > b.Right() ? a.Right() : b.Right();
        const int bottom = a.Bottom() > b.Bottom() ? a.Bottom() : b.Bottom();
        return {left, top, right - left, bottom - top};
    }

    friend constexpr bool operator==(const Rectangle&, const Rectangle&) = default;
};

inline constexpr Rectangle Rectangle::Empty{0, 0, 0, 0};

}  // namespace fxport
