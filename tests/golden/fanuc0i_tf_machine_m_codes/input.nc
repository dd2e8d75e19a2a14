(The machine's own M codes from the setup - m_codes - pass without warning - docs/setup.md.)
(Line 4 - M150 and line 6 - M151 are listed - line 5 - M152 is not - warning NCS-W05 - none moves anything.)
G98 G00 X20. Z2.
M150
M152
M151
M30
