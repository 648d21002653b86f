using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace Fitfeel.Examples
{
    /// <summary>
    /// The device states of a fitfeel recording (`fitfeel run` with outputs: [recording]; the
    /// format is framework/device/recording.h's), read exactly: the same doubles the run stepped.
    /// </summary>
    internal static class Recording
    {
        static readonly string[] Columns = {
            "t_s", "x_m", "y_m", "z_m", "qw_1", "qx_1", "qy_1", "qz_1", "vx_m/s", "vy_m/s",
            "vz_m/s", "wx_rad/s", "wy_rad/s", "wz_rad/s", "buttons_bits" };

        public static IEnumerable<DeviceState> Read(string path)
        {
            int[] at = null;
            int count = 0;
            int lineNumber = 0;
            foreach (string line in File.ReadLines(path))
            {
                ++lineNumber;
                if (line.StartsWith("#")) continue;
                string[] field = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
                if (at == null)
                {
                    // Looked up by name: a column added to the format does not shift the others.
                    at = new int[Columns.Length];
                    for (int i = 0; i < Columns.Length; ++i)
                    {
                        at[i] = Array.IndexOf(field, Columns[i]);
                        if (at[i] < 0) throw new InvalidDataException(path + ": no column " + Columns[i]);
                    }
                    count = field.Length;
                    continue;
                }
                if (field.Length != count)
                {
                    throw new InvalidDataException(path + ":" + lineNumber + ": " + field.Length +
                                                   " fields on a row of " + count + " columns");
                }
                Func<int, double> v = i => ExactDouble.Parse(field[at[i]]);
                var d = new DeviceState();
                d.Time = v(0);
                d.Position = new Vector3d(v(1), v(2), v(3));
                d.Orientation = new Quaterniond(v(4), v(5), v(6), v(7));
                d.Velocity = new Vector3d(v(8), v(9), v(10));
                d.AngularVelocity = new Vector3d(v(11), v(12), v(13));
                d.Buttons = uint.Parse(field[at[14]], CultureInfo.InvariantCulture);
                yield return d;
            }
        }
    }
}
