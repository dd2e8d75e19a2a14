(G83 on the 0i-TF with R beyond the initial level - R is signed from the initial level - docs/commands/g83_g87_lathe.md.)
(Line 5 - the tool at Z2. - R3. puts the R level at Z5. - away from the part - a rapid out there first.)
(Then the feed to the bottom Z-10. - 15 mm at F60 - 15 s plus 0.05 s - then a rapid back to the initial level Z2.)
G98 G00 X0 Z2.
G83 Z-10. R3. F60.
G80
M30
