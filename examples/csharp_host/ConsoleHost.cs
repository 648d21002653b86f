using System;
using System.Globalization;

namespace Fitfeel.Examples
{
    /// <summary>
    /// A C# host stepping fitfeel through the binding with recorded device states: prints every
    /// tick's wrench as the bits of its six doubles (force x y z, torque x y z), the form the C
    /// interface's replay test prints, so that the two compare with diff.
    /// Usage: mono fitfeel_csharp_host.exe SCENARIO RECORDING
    /// </summary>
    internal static class ConsoleHost
    {
        static int Main(string[] args)
        {
            if (args.Length != 2)
            {
                Console.Error.WriteLine("usage: fitfeel_csharp_host.exe SCENARIO RECORDING");
                return 2;
            }
            try
            {
                using (Scene scene = Scene.OpenFile(args[0]))
                {
                    long tick = 0;
                    double peak = 0.0;
                    foreach (DeviceState recorded in Recording.Read(args[1]))
                    {
                        DeviceState d = recorded;
                        Wrench w;
                        if (!scene.Step(ref d, out w))
                        {
                            Console.Error.WriteLine("tick " + tick + ": the scene ended before the recording");
                            return 1;
                        }
                        Console.WriteLine(tick + " " + Bits(w.Force.X) + " " + Bits(w.Force.Y) + " " +
                                          Bits(w.Force.Z) + " " + Bits(w.Torque.X) + " " +
                                          Bits(w.Torque.Y) + " " + Bits(w.Torque.Z));
                        peak = Math.Max(peak, Math.Abs(w.Force.Y));
                        ++tick;
                    }
                    Console.WriteLine(tick + " ticks, peak axial resistance " +
                                      peak.ToString("F3", CultureInfo.InvariantCulture) + " N");
                }
                return 0;
            }
            catch (ScenarioException e)
            {
                Console.Error.WriteLine("ScenarioException at " + e.File + " line " + e.Line +
                                        " column " + e.Column + " key '" + e.KeyPath + "': " +
                                        e.Message);
                return 2;
            }
            catch (FitfeelException e)
            {
                Console.Error.WriteLine("FitfeelException (" + e.Status + "): " + e.Message);
                return 1;
            }
        }

        static string Bits(double v)
        {
            return BitConverter.DoubleToInt64Bits(v).ToString("x16");
        }
    }
}
