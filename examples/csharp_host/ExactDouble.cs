using System;
using System.Globalization;
using System.Numerics;

namespace Fitfeel.Examples
{
    /// <summary>
    /// Decimal text to the nearest double (ties to even), as C's strtod. A recording's numbers
    /// are the shortest text that reads back to the recorded double, which only a correctly
    /// rounded parser guarantees; Mono's double.Parse misses by one ulp on about one such text in
    /// 700, so its result is taken as a first guess and moved to the nearest double, deciding by
    /// exact integer comparison with the midpoints to its neighbours.
    /// </summary>
    internal static class ExactDouble
    {
        public static double Parse(string text)
        {
            double guess = double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture);
            if (guess == 0.0 || double.IsInfinity(guess) || double.IsNaN(guess)) return guess;
            BigInteger digits;
            int exponent;
            Decimal(text, out digits, out exponent);
            long bits = BitConverter.DoubleToInt64Bits(Math.Abs(guess));
            while (true)
            {
                // Above the midpoint to the next double up: round up (a tie goes to the even one).
                int up = CompareWithMidpoint(digits, exponent, bits);
                if (up > 0 || (up == 0 && (bits & 1) != 0))
                {
                    ++bits;
                    continue;
                }
                if (bits > 1)
                {
                    int down = CompareWithMidpoint(digits, exponent, bits - 1);
                    if (down < 0 || (down == 0 && (bits & 1) != 0))
                    {
                        --bits;
                        continue;
                    }
                }
                break;
            }
            double magnitude = BitConverter.Int64BitsToDouble(bits);
            return guess < 0.0 ? -magnitude : magnitude;
        }

        // |text| = digits * 10^exponent.
        static void Decimal(string text, out BigInteger digits, out int exponent)
        {
            digits = BigInteger.Zero;
            exponent = 0;
            int i = 0;
            if (i < text.Length && (text[i] == '-' || text[i] == '+')) ++i;
            bool fraction = false;
            for (; i < text.Length; ++i)
            {
                char c = text[i];
                if (c == '.')
                {
                    fraction = true;
                }
                else if (c >= '0' && c <= '9')
                {
                    digits = digits * 10 + (c - '0');
                    if (fraction) --exponent;
                }
                else
                {
                    break;
                }
            }
            if (i < text.Length && (text[i] == 'e' || text[i] == 'E'))
            {
                exponent += int.Parse(text.Substring(i + 1), NumberStyles.AllowLeadingSign,
                                      CultureInfo.InvariantCulture);
            }
        }

        // Sign of digits * 10^exponent minus the midpoint between the positive double `bits` and
        // the next one up, (2m + 1) * 2^(e - 1) for bits = m * 2^e.
        static int CompareWithMidpoint(BigInteger digits, int exponent, long bits)
        {
            long fieldExponent = (bits >> 52) & 0x7ff;
            long mantissa = bits & 0xfffffffffffffL;
            int e;
            if (fieldExponent == 0)
            {
                e = -1074;
            }
            else
            {
                mantissa |= 1L << 52;
                e = (int)fieldExponent - 1075;
            }
            BigInteger left = digits, right = new BigInteger(2 * mantissa + 1);
            int twos = e - 1;
            if (exponent >= 0) left *= BigInteger.Pow(10, exponent);
            else right *= BigInteger.Pow(10, -exponent);
            if (twos >= 0) right <<= twos;
            else left <<= -twos;
            return left.CompareTo(right);
        }
    }
}
