namespace Fitfeel
{
    /// <summary>The C interface's status codes (FITFEEL_OK ... FITFEEL_ERROR in fitfeel.h).</summary>
    public enum Status
    {
        Ok = 0,
        /// <summary>Every tick of the scene's run.duration is done.</summary>
        Done = 1,
        /// <summary>A null pointer or a handle in the wrong state.</summary>
        InvalidArgument = -1,
        /// <summary>A refused scenario: file:line:column, key, expected, found.</summary>
        ScenarioError = -2,
        /// <summary>Anything else the framework refused (the text says what).</summary>
        Error = -3,
    }
}
