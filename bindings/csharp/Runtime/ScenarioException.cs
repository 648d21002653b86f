using System.Text.RegularExpressions;

namespace Fitfeel
{
    /// <summary>
    /// A scenario the C interface refused (FITFEEL_SCENARIO_ERROR). Message is the CLI's located
    /// text, "file:line:column: key.path: expected ..., found ..."; its parts are also given
    /// apart, so that an editor can point at the offending value.
    /// </summary>
    public sealed class ScenarioException : FitfeelException
    {
        // The key path is a dotted name without spaces; YAML syntax errors have none.
        static readonly Regex Located =
            new Regex(@"^(?<file>.*?):(?<line>\d+):(?<column>\d+): (?:(?<key>[^\s:]+): )?");

        public ScenarioException(string message) : base(Status.ScenarioError, message)
        {
            Match m = Located.Match(message);
            if (!m.Success) return;
            File = m.Groups["file"].Value;
            Line = int.Parse(m.Groups["line"].Value);
            Column = int.Parse(m.Groups["column"].Value);
            KeyPath = m.Groups["key"].Value;
        }

        /// <summary>The scenario file (or the name given to Scene.OpenYaml); null if unlocated.</summary>
        public string File { get; private set; }
        /// <summary>1-based; 0 if unlocated.</summary>
        public int Line { get; private set; }
        /// <summary>1-based; 0 if unlocated.</summary>
        public int Column { get; private set; }
        /// <summary>The refused key, e.g. "device.speed"; empty for a YAML syntax error.</summary>
        public string KeyPath { get; private set; }
    }
}
