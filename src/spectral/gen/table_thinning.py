"""Thinning and printing of tabulated optical constants for kiln's embedded tables (shared by the
generators in this folder): keeps a table's own points such that every dropped point lies
close to the straight line between the kept ones around it (kiln interpolates linearly in
wavelength)."""


def thin(rows, close):
    """rows: (wavelength, n, k) in increasing wavelength. close(interpolated, actual, column)
    says whether a dropped point's n (column 1) or k (column 2) is near enough the line. From
    each kept point, keeps the farthest next point that leaves every point between close."""
    def within(a, b, between):
        for row in between:
            t = (row[0] - a[0]) / (b[0] - a[0])
            for c in (1, 2):
                if not close(a[c] + t * (b[c] - a[c]), row[c], c):
                    return False
        return True

    kept = [rows[0]]
    i = 0
    while i < len(rows) - 1:
        j = i + 1
        while j + 1 < len(rows) and within(rows[i], rows[j + 1], rows[i + 1:j + 1]):
            j += 1
        kept.append(rows[j])
        i = j
    return kept


def print_array(declaration, items):
    """Prints a C++ array `declaration = { items }` wrapped at 99 columns."""
    print(f"{declaration} = {{")
    line = "   "
    for item in items:
        if len(line) + len(item) + 1 > 99:
            print(line)
            line = "   "
        line += " " + item
    print(line)
    print("};\n")
